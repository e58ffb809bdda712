#include "common/kernel_table.h"

#include <algorithm>
#include <cmath>

namespace nimbus::media {

double kernelSegment(double beta, double mu) {
    if (!(beta < 1.0)) return 0.0;
    const double h = std::sqrt(1.0 - beta * beta);
    const double end = std::clamp(mu, -h, h);
    const double sk = std::sqrt(4.5);
    // ∫ e^(−k s²) ds = √π/(2√k) · erf(√k s)
    return std::exp(-4.5 * beta * beta) * 0.88622692545275801 / sk * (std::erf(sk * end) + std::erf(sk * h));
}

std::vector<float> kernelTableValues(int betas, int mus) {
    std::vector<float> values(static_cast<std::size_t>(betas) * static_cast<std::size_t>(mus));
    for (int j = 0; j < mus; ++j) {
        const double mu = 2.0 * j / (mus - 1) - 1.0;
        for (int i = 0; i < betas; ++i)
            values[static_cast<std::size_t>(j) * static_cast<std::size_t>(betas) + static_cast<std::size_t>(i)] =
                static_cast<float>(kernelSegment(static_cast<double>(i) / (betas - 1), mu));
    }
    return values;
}

gpu::Texture createKernelTable() {
    gpu::Texture table({GL_TEXTURE_2D, GL_R32F, kKernelTableBetas, kKernelTableMus, 1, 1});
    const std::vector<float> values = kernelTableValues(kKernelTableBetas, kKernelTableMus);
    glTextureSubImage2D(table.id(), 0, 0, 0, kKernelTableBetas, kKernelTableMus, GL_RED, GL_FLOAT, values.data());
    glTextureParameteri(table.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(table.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(table.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(table.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return table;
}

}  // namespace nimbus::media
