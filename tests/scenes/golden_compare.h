#pragma once
// The golden-image tolerance (tests/golden/README.md says why): rasterisers may round edges
// differently, so a few pixels at geometric edges may differ by a lot; everywhere else the image
// must match closely.
//   outlier     a pixel whose largest channel difference exceeds kOutlierThreshold (linear radiance)
//   edge pixel  a pixel whose 3×3 neighbourhood in the golden spans more than kOutlierThreshold in some channel
// Pass: no non-finite pixel; at most kMaxOutlierFraction of the pixels are outliers, all of them edge
// pixels; rel-RMSE (image_metrics.h: sqrt(mean (A−B)²) / mean luminance(B)) over the image with the
// outliers taken as equal is at most kMaxRelRmse.
#include <algorithm>
#include <sstream>
#include <string>

#include "nimbus/assets/image_io.h"
#include "nimbus/media/reference/image_metrics.h"

namespace nimbus::test {

inline constexpr float kOutlierThreshold = 0.01f;
inline constexpr double kMaxOutlierFraction = 0.005;
inline constexpr double kMaxRelRmse = 0.005;

struct GoldenComparison {
    media::reference::ImageMetrics whole;  // the plain metrics, for the log
    double relRmseWithoutOutliers = 0.0;
    std::size_t outliers = 0;
    std::size_t outliersOffEdges = 0;
    std::size_t pixels = 0;
    std::string firstOffEdge;  // "(x, y)" of the first outlier that is not at an edge

    bool passes() const {
        return whole.nonfinite == 0 && outliersOffEdges == 0 &&
               static_cast<double>(outliers) <= kMaxOutlierFraction * static_cast<double>(pixels) && relRmseWithoutOutliers <= kMaxRelRmse;
    }
    std::string describe() const {
        std::ostringstream text;
        text << "rel_rmse " << whole.relRmse << " (without outliers " << relRmseWithoutOutliers << ", limit " << kMaxRelRmse
             << "), outliers " << outliers << " of " << pixels << " pixels (limit " << kMaxOutlierFraction * static_cast<double>(pixels)
             << "), off edges " << outliersOffEdges << (firstOffEdge.empty() ? "" : " first at " + firstOffEdge) << ", nonfinite "
             << whole.nonfinite << ", psnr " << whole.psnr;
        return text.str();
    }
};

inline float largestChannelDifference(const glm::vec3& a, const glm::vec3& b) {
    const glm::vec3 d = glm::abs(a - b);
    return std::max({d.x, d.y, d.z});
}

// Throws std::invalid_argument when the sizes differ.
inline GoldenComparison compareWithGolden(const assets::RgbImage& actual, const assets::RgbImage& golden) {
    GoldenComparison c;
    c.whole = media::reference::compareImages(actual, golden);
    c.pixels = golden.pixelCount();
    assets::RgbImage withoutOutliers = actual;
    for (int y = 0; y < golden.height; ++y)
        for (int x = 0; x < golden.width; ++x) {
            if (!(largestChannelDifference(actual.at(x, y), golden.at(x, y)) > kOutlierThreshold)) continue;
            ++c.outliers;
            withoutOutliers.set(x, y, golden.at(x, y));
            glm::vec3 lo(golden.at(x, y)), hi(lo);
            for (int j = std::max(y - 1, 0); j <= std::min(y + 1, golden.height - 1); ++j)
                for (int i = std::max(x - 1, 0); i <= std::min(x + 1, golden.width - 1); ++i) {
                    lo = glm::min(lo, golden.at(i, j));
                    hi = glm::max(hi, golden.at(i, j));
                }
            const glm::vec3 span = hi - lo;
            if (std::max({span.x, span.y, span.z}) <= kOutlierThreshold) {
                ++c.outliersOffEdges;
                if (c.firstOffEdge.empty()) {
                    std::ostringstream where;
                    where << "(" << x << ", " << y << ")";
                    c.firstOffEdge = where.str();
                }
            }
        }
    c.relRmseWithoutOutliers = media::reference::compareImages(withoutOutliers, golden).relRmse;
    return c;
}

}  // namespace nimbus::test
