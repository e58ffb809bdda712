// Tests engine/assets/src/image_io.cpp's display encoding: the default clips L · exposure at 1, the
// filmic curve rolls highlights off (monotonic, Narkowicz's ACES fit), and neither touches EXR.
#include "nimbus/assets/image_io.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace nimbus::assets {
namespace {

TEST(ImageIo, FilmicRollsHighlightsOffMonotonically) {
    EXPECT_EQ(applyToneCurve(2.0f, ToneCurve::None), 2.0f);
    EXPECT_EQ(applyToneCurve(0.0f, ToneCurve::Filmic), 0.0f);
    float previous = 0.0f;
    for (int i = 1; i <= 1000; ++i) {
        const float x = 0.02f * static_cast<float>(i);
        const float y = applyToneCurve(x, ToneCurve::Filmic);
        if (x < 5.0f) {
            EXPECT_GT(y, previous) << x;
        }
        EXPECT_GE(y, previous);
        EXPECT_LE(y, 1.0f);
        previous = y;
    }
    EXPECT_NEAR(applyToneCurve(1.0f, ToneCurve::Filmic), 2.54f / 3.16f, 1e-6f);  // (2.51 + 0.03) / (2.43 + 0.59 + 0.14)
}

TEST(ImageIo, DisplayEncodingAppliesTheCurveAfterTheExposure) {
    RgbImage image;
    image.width = 2;
    image.height = 1;
    image.rgb = {0.5f, 4.0f, 0.0f, 0.25f, 0.25f, 0.25f};
    const std::vector<std::uint8_t> plain = displayEncode(image, 2.0f);
    EXPECT_EQ(plain[0], 255);  // 1.0 clips to white
    EXPECT_EQ(plain[1], 255);
    const std::vector<std::uint8_t> filmic = displayEncode(image, 2.0f, ToneCurve::Filmic);
    EXPECT_LT(filmic[0], filmic[1]);  // 1.0 and 8.0 stay apart
    EXPECT_EQ(filmic[0], static_cast<std::uint8_t>(std::lround(255.0f * srgbEncode(applyToneCurve(1.0f, ToneCurve::Filmic)))));
}

}  // namespace
}  // namespace nimbus::assets
