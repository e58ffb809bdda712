#include "nimbus/media/block_partition.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace nimbus::media {
namespace {

std::uint64_t spreadBits(std::uint64_t v) {
    v &= 0x1fffff;
    v = (v | v << 32) & 0x1f00000000ffffULL;
    v = (v | v << 16) & 0x1f0000ff0000ffULL;
    v = (v | v << 8) & 0x100f00f00f00f00fULL;
    v = (v | v << 4) & 0x10c30c30c30c30c3ULL;
    v = (v | v << 2) & 0x1249249249249249ULL;
    return v;
}

}  // namespace

std::uint64_t mortonCode(std::uint32_t x, std::uint32_t y, std::uint32_t z) {
    return spreadBits(x) | spreadBits(y) << 1 | spreadBits(z) << 2;
}

int automaticBlockCount(std::size_t particles) {
    if (particles == 0) return 0;
    return std::clamp(static_cast<int>(std::lround(std::sqrt(static_cast<double>(particles)))), 1, 1024);
}

BlockPartition partitionIntoBlocks(const ParticleSet& particles, int blockCount) {
    BlockPartition out;
    const std::size_t n = particles.size();
    if (n == 0) return out;
    const std::size_t blocks = std::min<std::size_t>(n, static_cast<std::size_t>(blockCount > 0 ? blockCount : automaticBlockCount(n)));

    double meanRadius = 0.0;
    glm::dvec3 lo(std::numeric_limits<double>::infinity());
    for (std::size_t i = 0; i < n; ++i) {
        meanRadius += particles.radius[i];
        lo = glm::min(lo, particles.position[i]);
    }
    meanRadius /= static_cast<double>(n);
    // World-anchored lattice: cell a power of two (stable while the mean radius stays in one octave),
    // origin on a coarse multiple of 2^20 cells (stable while the medium stays in one such region).
    const double cell = std::exp2(std::floor(std::log2(std::max(meanRadius, 1e-6))));
    const double coarse = cell * static_cast<double>(1 << 20);
    const glm::dvec3 anchor = glm::floor(lo / coarse) * coarse;
    std::vector<std::uint64_t> codes(n);
    for (std::size_t i = 0; i < n; ++i) {
        const glm::dvec3 c = glm::clamp(glm::floor((particles.position[i] - anchor) / cell), glm::dvec3(0.0), glm::dvec3(2097151.0));
        codes[i] = mortonCode(static_cast<std::uint32_t>(c.x), static_cast<std::uint32_t>(c.y), static_cast<std::uint32_t>(c.z));
    }
    out.order.resize(n);
    std::iota(out.order.begin(), out.order.end(), 0u);
    std::stable_sort(out.order.begin(), out.order.end(), [&](std::uint32_t a, std::uint32_t b) { return codes[a] < codes[b]; });

    out.blocks.resize(blocks);
    for (std::size_t b = 0; b < blocks; ++b) {
        // Even split: block b holds [b·n/blocks, (b+1)·n/blocks).
        const std::size_t first = b * n / blocks, last = (b + 1) * n / blocks;
        Block& block = out.blocks[b];
        block.first = static_cast<std::uint32_t>(first);
        block.count = static_cast<std::uint32_t>(last - first);
        glm::dvec3 sum(0.0);
        for (std::size_t k = first; k < last; ++k) sum += particles.position[out.order[k]];
        block.centre = sum / static_cast<double>(last - first);
        double radiusSum = 0.0;
        for (std::size_t k = first; k < last; ++k) {
            const std::uint32_t i = out.order[k];
            block.radius = std::max(block.radius, glm::length(particles.position[i] - block.centre) + particles.radius[i]);
            radiusSum += particles.radius[i];
        }
        block.meanParticleRadius = static_cast<float>(radiusSum / static_cast<double>(last - first));
    }
    return out;
}

}  // namespace nimbus::media
