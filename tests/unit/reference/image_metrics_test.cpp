// Tests plugins/participating_media/reference/src/image_metrics.cpp against hand-computed values.
#include "nimbus/media/reference/image_metrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace nimbus::media::reference {
namespace {

assets::RgbImage filled(int w, int h, float v) {
    assets::RgbImage image(w, h);
    std::fill(image.rgb.begin(), image.rgb.end(), v);
    return image;
}

TEST(ImageMetrics, IdenticalImages) {
    const assets::RgbImage a = filled(8, 4, 0.3f);
    const ImageMetrics m = compareImages(a, a);
    EXPECT_EQ(m.relRmse, 0.0);
    EXPECT_EQ(m.psnr, kPsnrCap);
    EXPECT_EQ(m.p99Abs, 0.0);
    EXPECT_EQ(m.nonfinite, 0u);
    EXPECT_EQ(m.comparedPixels, 32u);
}

TEST(ImageMetrics, UniformOffset) {
    const assets::RgbImage b = filled(10, 10, 0.5f), a = filled(10, 10, 0.6f);
    const ImageMetrics m = compareImages(a, b);
    EXPECT_NEAR(m.relRmse, 0.1 / 0.5, 1e-6);  // RMSE 0.1, luminance of grey 0.5 is 0.5
    EXPECT_NEAR(m.p99Abs, 0.1, 1e-6);
    const double d = assets::srgbEncode(0.6f) - assets::srgbEncode(0.5f);
    EXPECT_NEAR(m.psnr, -20.0 * std::log10(d), 1e-4);
}

TEST(ImageMetrics, PercentileIsNearestRank) {
    // 100 pixels, the red channel differs by k/100 for pixel k: 300 values, 200 of them 0.
    assets::RgbImage a = filled(100, 1, 0.0f), b = filled(100, 1, 0.0f);
    for (int k = 0; k < 100; ++k) a.rgb[3 * k] = static_cast<float>(k + 1) / 100.0f;
    // rank ceil(0.99 · 300) = 297: sorted values are 200 zeros, then 0.01 ... 1.00 -> the 97th, 0.97.
    EXPECT_NEAR(compareImages(a, b).p99Abs, 0.97, 1e-6);
}

TEST(ImageMetrics, NonFinitePixelsAreCountedAndLeftOut) {
    assets::RgbImage a = filled(4, 1, 0.5f);
    const assets::RgbImage b = filled(4, 1, 0.5f);
    a.rgb[1] = std::numeric_limits<float>::quiet_NaN();
    a.rgb[6] = std::numeric_limits<float>::infinity();
    const ImageMetrics m = compareImages(a, b);
    EXPECT_EQ(m.nonfinite, 2u);
    EXPECT_EQ(m.comparedPixels, 2u);
    EXPECT_EQ(m.relRmse, 0.0);
    EXPECT_EQ(m.psnr, kPsnrCap);
    const assets::RgbImage allNan = filled(2, 2, std::numeric_limits<float>::quiet_NaN());
    const ImageMetrics none = compareImages(allNan, filled(2, 2, 0.5f));
    EXPECT_EQ(none.nonfinite, 4u);
    EXPECT_TRUE(std::isnan(none.relRmse));
}

TEST(ImageMetrics, BlackReferenceAndSizeMismatch) {
    EXPECT_TRUE(std::isinf(compareImages(filled(2, 2, 0.1f), filled(2, 2, 0.0f)).relRmse));
    EXPECT_EQ(compareImages(filled(2, 2, 0.0f), filled(2, 2, 0.0f)).relRmse, 0.0);
    EXPECT_THROW(compareImages(filled(2, 2, 0.0f), filled(2, 3, 0.0f)), std::invalid_argument);
}

}  // namespace
}  // namespace nimbus::media::reference
