// Offscreen media (Jendersie's offscreen particles, media_depth_used_pass.cpp + shaders/common/upsample.glsl in
// compose): `particles` at media_scale 0.5 and 0.25 on cloud.gltf, where a wing crosses the cloud, against the
// same frame at full resolution and against the reference.
//   - The upsampled frame stays close to the full-resolution one (rel-RMSE bound per scale).
//   - Depth awareness pays: with the edge test switched off (upsample_threshold=10 makes every
//     texel match, i.e. plain bilinear), smoke bleeds over the wing's silhouette and the error
//     against the full-resolution frame is higher.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "media_test_support.h"

namespace nimbus::test::media {
namespace {

constexpr int kWidth = 192, kHeight = 108;

double errorAgainstFullResolution(const std::vector<std::string>& settings) {
    sandbox::Session full(particlesMode(contentScene("cloud")));
    const assets::RgbImage reference = full.renderRealtime(kWidth, kHeight);
    sandbox::Session low(particlesMode(contentScene("cloud"), 0.0, settings));
    const assets::RgbImage image = low.renderRealtime(kWidth, kHeight);
    const auto metrics = nimbus::media::reference::compareImages(image, reference);
    EXPECT_EQ(metrics.nonfinite, 0u);
    return metrics.relRmse;
}

class OffscreenMedia : public GlSceneTest {};

// Measured (192×108): 0.5 → 0.24 %, 0.25 → 0.74 % against the full-resolution frame.
TEST_F(OffscreenMedia, StaysCloseToTheFullResolutionFrame) {
    const double half = errorAgainstFullResolution({"media_scale=0.5"});
    const double quarter = errorAgainstFullResolution({"media_scale=0.25"});
    std::printf("[ measured ] cloud media_scale 0.5: %.4f, 0.25: %.4f against full resolution\n", half, quarter);
    EXPECT_LE(half, 0.004);
    EXPECT_LE(quarter, 0.011);
    EXPECT_LT(half, quarter);
}

TEST_F(OffscreenMedia, DepthAwareUpsamplingBeatsPlainBilinearAtTheWingsSilhouette) {
    const double aware = errorAgainstFullResolution({"media_scale=0.25"});
    const double plain = errorAgainstFullResolution({"media_scale=0.25", "upsample_threshold=10"});
    std::printf("[ measured ] cloud media_scale 0.25: depth-aware %.4f, plain bilinear %.4f\n", aware, plain);
    EXPECT_LT(aware, plain);
}

}  // namespace
}  // namespace nimbus::test::media
