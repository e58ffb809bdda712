// `particles` mode against the reference renderer (docs/design.md §6) on every content scene with media,
// at the time tools/scenegen/make_scenes.py renders it (TIMES), in each quality tier against one
// reference render: rel-RMSE = RMSE of linear RGB / mean luminance of the reference
// (image_metrics.h), and no non-finite pixel. The exact tier's bound per scene is about 1.5 × what
// was measured when the test was written. The balanced and fast tiers' bounds are the issue's
// (balanced: 1.5 × the exact tier's error, where the per-particle fit reaches it; fast: 3%, 5% for
// campfire and explosion) or, where a tier is beyond them, about 1.25 × what it measured, with why.
//
// 192×108 keeps every reference render near a second; the errors measured here are within 0.3 %
// (absolute) of those at 320×180 (smoke 1.5 %, cloud 1.2 %, jet 0.8 %, explosion 4.1 %, campfire 3.1 %).
#include <gtest/gtest.h>

#include <cstdio>
#include <ostream>
#include <string>

#include "media_test_support.h"
#include "nimbus/base/settings.h"

namespace nimbus::test::media {
namespace {

constexpr int kWidth = 192, kHeight = 108;

struct ContentCase {
    const char* scene;
    double time;      // make_scenes.py TIMES (0 where the scene has no emitter)
    double measured;  // rel-RMSE when the bound was set (documentation only)
    double bound;
    double balancedBound;
    double fastBound;
};

void PrintTo(const ContentCase& c, std::ostream* os) { *os << c.scene << " at t=" << c.time << " s"; }

class ContentVsReference : public GlSceneTest, public ::testing::WithParamInterface<ContentCase> {};

TEST_P(ContentVsReference, RelRmseWithinTheScenesBound) {
    const ContentCase& c = GetParam();
    sandbox::Session session(particlesMode(contentScene(c.scene), c.time));
    const assets::RgbImage reference = renderReference(session, kWidth, kHeight);
    const std::pair<const char*, double> tiers[] = {{"exact", c.bound}, {"balanced", c.balancedBound}, {"fast", c.fastBound}};
    for (const auto& [quality, bound] : tiers) {
        session.app().resource<Settings>().set("quality", quality, "test");
        const auto metrics = nimbus::media::reference::compareImages(session.renderRealtime(kWidth, kHeight), reference);
        EXPECT_EQ(metrics.nonfinite, 0u) << c.scene << ", " << quality;
        EXPECT_EQ(metrics.comparedPixels, static_cast<std::size_t>(kWidth) * kHeight) << c.scene;
        EXPECT_LE(metrics.relRmse, bound) << c.scene << ", " << quality << (std::string(quality) == "exact" ? ": measured " + std::to_string(c.measured) + " when the bound was set" : "");
        RecordProperty(std::string("rel_rmse_") + quality, std::to_string(metrics.relRmse));
        std::printf("[ measured ] %s t=%.2f %s rel_rmse=%.4f (bound %.3f)\n", c.scene, c.time, quality, metrics.relRmse, bound);
    }
}

INSTANTIATE_TEST_SUITE_P(
    Content, ContentVsReference,
    ::testing::Values(
        // A smoke column half in a building's shadow.
        ContentCase{"smoke", 8.0, 0.0142, 0.022, 0.022, 0.03},
        // A fire with a point light inside it: the light's 1/d² peaks far more sharply than a particle's
        // kernel varies, so its light is integrated along each particle's segment and the overlapping
        // particles' order corrected (local_light_segment.glsl, lamp_neighbourhood.glsl); 9.7 % with
        // one shading point per particle.
        // Balanced beyond 1.5 × exact (3.1 %): the fragments' lamp term has six nodes near the lamp and
        // no compositing-order correction among the fire's particles (3.7 % at 192×108).
        ContentCase{"campfire", 4.0, 0.0309, 0.046, 0.046, 0.05},
        // Balanced beyond 1.5 × exact (1.4 %): a pixel-thin dense trail brightens sharply at its sunward
        // rim, which the per-particle fit follows only in part (2.0 % at 192×108).
        ContentCase{"jet", 6.0, 0.0081, 0.012, 0.025, 0.03},
        // Emissive fireball: the emission over life changes fast, the burst is dense.
        ContentCase{"explosion", 0.8, 0.0413, 0.062, 0.062, 0.05},
        ContentCase{"cloud", 0.0, 0.0110, 0.017, 0.017, 0.03},
        // 8000 particles; the second with an airliner inside the cloud.
        ContentCase{"cumulus", 0.0, 0.0008, 0.0014, 0.0014, 0.03},
        ContentCase{"cumulus_aircraft", 0.0, 0.0019, 0.0038, 0.0038, 0.03},
        // A smoke plume in height fog: every particle fogged at one distance, the reference at every sample.
        ContentCase{"fog_smoke", 8.0, 0.0072, 0.011, 0.011, 0.03}),
    [](const ::testing::TestParamInfo<ContentCase>& param) { return std::string(param.param.scene); });

}  // namespace
}  // namespace nimbus::test::media
