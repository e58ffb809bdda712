#pragma once
// How far image A is from image B (usually a real-time frame against the reference): the numbers
// `sandbox compare` prints (docs/design.md §5, §6).
//
//   rel_rmse  = sqrt(mean over pixels and RGB channels of (A - B)²) / mean Rec.709 luminance of B
//               (linear values; +inf when B's mean luminance is 0 and A differs, 0 when equal)
//   psnr      = 10 log10(1 / MSE) over sRGB-encoded values clamped to [0, 1]; 200 dB when identical
//               (the cap: any real difference of 8-bit images is far below it)
//   p99_abs   = the 99th percentile (nearest rank) of |A - B| over all linear channel values
//   nonfinite = the number of pixels of A with a NaN or Inf channel
// Every metric but nonfinite uses only pixels where both A and B are finite; with no such pixel the
// metrics are NaN (printed as null).
//
// Does not: read files (sandbox compare does), align or resize images.
#include <cstddef>

#include "nimbus/assets/image_io.h"

namespace nimbus::media::reference {

inline constexpr double kPsnrCap = 200.0;

struct ImageMetrics {
    double relRmse = 0.0;
    double psnr = kPsnrCap;
    double p99Abs = 0.0;
    std::size_t nonfinite = 0;
    std::size_t comparedPixels = 0;  // pixels finite in both images
};

// Throws std::invalid_argument when the sizes differ (callers name the files in their message).
ImageMetrics compareImages(const assets::RgbImage& a, const assets::RgbImage& b);

// Rec.709 / sRGB luminance of linear RGB.
inline double luminance(double r, double g, double b) { return 0.2126 * r + 0.7152 * g + 0.0722 * b; }

}  // namespace nimbus::media::reference
