#include "nimbus/media/reference/image_metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace nimbus::media::reference {

ImageMetrics compareImages(const assets::RgbImage& a, const assets::RgbImage& b) {
    if (a.width != b.width || a.height != b.height)
        throw std::invalid_argument("sizes differ: " + std::to_string(a.width) + "x" + std::to_string(a.height) + " vs " +
                                    std::to_string(b.width) + "x" + std::to_string(b.height));
    ImageMetrics m;
    const std::size_t pixels = a.pixelCount();
    std::vector<double> absErrors;
    absErrors.reserve(3 * pixels);
    double squared = 0.0, srgbSquared = 0.0, luminanceB = 0.0;
    for (std::size_t p = 0; p < pixels; ++p) {
        const float* pa = &a.rgb[3 * p];
        const float* pb = &b.rgb[3 * p];
        const bool finiteA = std::isfinite(pa[0]) && std::isfinite(pa[1]) && std::isfinite(pa[2]);
        const bool finiteB = std::isfinite(pb[0]) && std::isfinite(pb[1]) && std::isfinite(pb[2]);
        if (!finiteA) ++m.nonfinite;
        if (!finiteA || !finiteB) continue;
        ++m.comparedPixels;
        for (int c = 0; c < 3; ++c) {
            const double d = static_cast<double>(pa[c]) - static_cast<double>(pb[c]);
            squared += d * d;
            absErrors.push_back(std::abs(d));
            const double s = static_cast<double>(assets::srgbEncode(pa[c])) - static_cast<double>(assets::srgbEncode(pb[c]));
            srgbSquared += s * s;
        }
        luminanceB += luminance(pb[0], pb[1], pb[2]);
    }
    if (m.comparedPixels == 0) {
        const double nan = std::numeric_limits<double>::quiet_NaN();
        m.relRmse = m.psnr = m.p99Abs = nan;
        return m;
    }
    const double n = static_cast<double>(m.comparedPixels);
    const double rmse = std::sqrt(squared / (3.0 * n));
    const double meanLuminance = luminanceB / n;
    if (rmse == 0.0) {
        m.relRmse = 0.0;
    } else {
        m.relRmse = meanLuminance > 0.0 ? rmse / meanLuminance : std::numeric_limits<double>::infinity();
    }
    const double mse = srgbSquared / (3.0 * n);
    m.psnr = mse > 0.0 ? std::min(kPsnrCap, 10.0 * std::log10(1.0 / mse)) : kPsnrCap;
    // Nearest rank: the smallest value with at least 99% of the values at or below it.
    const std::size_t rank = static_cast<std::size_t>(std::ceil(0.99 * static_cast<double>(absErrors.size())));
    const std::size_t index = std::max<std::size_t>(rank, 1) - 1;
    std::nth_element(absErrors.begin(), absErrors.begin() + static_cast<std::ptrdiff_t>(index), absErrors.end());
    m.p99Abs = absErrors[index];
    return m;
}

}  // namespace nimbus::media::reference
