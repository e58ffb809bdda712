// slices/light_slice_pass.cpp: a lamp's own views drawn at their own resolution (fewer texels than
// the array holds for the sun) and scaled up into their layers give the frame the full resolution
// gives, within what the coarser texels change; and the frames come from the small views (the
// slice_resolution setting draws every view at the array's, so the two differ).
#include <gtest/gtest.h>

#include <cstdio>

#include "media_test_support.h"
#include "nimbus/base/settings.h"

namespace nimbus::test::media {
namespace {

constexpr int kWidth = 192, kHeight = 108;

class LightSlices : public GlSceneTest {};

TEST_F(LightSlices, ALampsViewsDrawnSmallMatchTheArraysResolution) {
    // campfire: the sun's view wants 48 texels, the lamp's six cube faces 16 (a point light inside
    // the fire). Fast tier, the figures of docs/PERFORMANCE.md's lamp section.
    sandbox::Session session(particlesMode(contentScene("campfire"), 4.0, {"quality=fast"}));
    const assets::RgbImage small = session.renderRealtime(kWidth, kHeight);
    const int resolution = 48;
    session.app().resource<Settings>().set("slice_resolution", std::to_string(resolution), "test");
    const assets::RgbImage full = session.renderRealtime(kWidth, kHeight);
    const auto metrics = nimbus::media::reference::compareImages(small, full);
    std::printf("[ measured ] campfire fast, lamp faces at 16 texels against all at %d: rel_rmse=%.4f\n", resolution, metrics.relRmse);
    EXPECT_EQ(metrics.nonfinite, 0u);
    // 0.50 % when written; the reference errs 4.2 % against either.
    EXPECT_LT(metrics.relRmse, 0.015) << "the scaled-up faces hold the lamp's optical depth";
    EXPECT_GT(metrics.relRmse, 0.0) << "the faces were drawn small (else the two frames are the same)";
}

}  // namespace
}  // namespace nimbus::test::media
