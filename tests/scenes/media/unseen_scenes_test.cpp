// Scenes the renderer was not tuned on, built from the same extension (issue acceptance: "scenes we
// have not seen ... must also land within 10 %"): `particles` mode against the reference, rel-RMSE
// ≤ 10 % and no non-finite pixel. The scenes are tests/data/media_scenes/unseen_*.gltf, written by
// generate_media_scenes.py (seeded); the docstring of each scene function there says what it varies.
//
// The bound is the 10 % for every scene and is never loosened per scene.
// Measured values below are at 192×108, when the test was written.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "media_test_support.h"
#include "nimbus/base/settings.h"

namespace nimbus::test::media {
namespace {

constexpr int kWidth = 192, kHeight = 108;
constexpr double kUnseenBound = 0.10;
// The fast tier's: it lights each particle once, from nine rays through it, with slices at two
// texels per particle radius (quality preset `fast`). 15 %: three times the fast bound on
// the content scenes (3–5 %); measured at most 7.6 % (unseen_point_inside_dense, a lamp in a τ 3
// cloud), 5.7 % where no lamp lies inside the medium (unseen_forward_glow).
constexpr double kUnseenFastBound = 0.15;

class UnseenScenes : public GlSceneTest {
protected:
    // Exact and balanced within 10 %, fast within its bound, all against one reference render.
    static void expectWithinBound(const std::string& scene, double fastBound = kUnseenFastBound) {
        sandbox::Session session(particlesMode(mediaScene(scene), 0.0));
        const assets::RgbImage reference = renderReference(session, kWidth, kHeight);
        const std::pair<const char*, double> tiers[] = {{"exact", kUnseenBound}, {"balanced", kUnseenBound}, {"fast", fastBound}};
        for (const auto& [quality, bound] : tiers) {
            session.app().resource<Settings>().set("quality", quality, "test");
            const auto metrics = nimbus::media::reference::compareImages(session.renderRealtime(kWidth, kHeight), reference);
            EXPECT_EQ(metrics.nonfinite, 0u) << scene << ", " << quality;
            EXPECT_LE(metrics.relRmse, bound) << scene << ", " << quality;
            std::printf("[ measured ] %s %s rel_rmse=%.4f (bound %.2f)\n", scene.c_str(), quality, metrics.relRmse, bound);
        }
    }
};

// Optical thickness along the view (the generator's `tau`) from 0.1 to 10.
TEST_F(UnseenScenes, ThinHaze) { expectWithinBound("unseen_thin_haze"); }                    // tau 0.1: 0.25 %
TEST_F(UnseenScenes, ThickCumulus) { expectWithinBound("unseen_thick_cumulus"); }            // tau 10: 0.43 %
// Phase functions: HG g from -0.5 to 0.9, Rayleigh.
TEST_F(UnseenScenes, Backscatter) { expectWithinBound("unseen_backscatter"); }               // g -0.5, no ambient: 3.2 %
TEST_F(UnseenScenes, ForwardGlow) { expectWithinBound("unseen_forward_glow"); }              // g 0.9 towards the sun: 0.55 %
TEST_F(UnseenScenes, Rayleigh) { expectWithinBound("unseen_rayleigh"); }                     // per-channel albedo: 0.78 %
// Emission, albedo 0 and 1 side by side, coloured suns.
TEST_F(UnseenScenes, Emissive) { expectWithinBound("unseen_emissive"); }                     // 0.05 %
TEST_F(UnseenScenes, AlbedoMix) { expectWithinBound("unseen_albedo_mix"); }                  // 0.29 %
// Spot and point lights, outside, near and inside the medium.
TEST_F(UnseenScenes, SpotIntoFog) { expectWithinBound("unseen_spot_into_fog"); }             // 0.77 %
TEST_F(UnseenScenes, PointNearCloud) { expectWithinBound("unseen_point_near"); }             // 2.8 %
TEST_F(UnseenScenes, PointInsideThinMedium) { expectWithinBound("unseen_point_inside"); }    // tau 0.5: 0.3 / 1.3 / 1.6 %
// A point light inside a dense cloud (tau 3): radiance peaks at ~34 in a few pixels around the
// lamp, and rel-RMSE divides by a mean of ~0.3, so those pixels must be right within a few percent.
// 6.8 %; it was 108 % while one shading point per particle took the lamp's 1/d² peak, its phase
// angle and its transmittance, and compositing order dimmed the peak by whole particles
// (lighting.glsl segmentSource, local_light_segment.glsl, lamp_neighbourhood.glsl). Balanced and
// fast 7.7 % and 7.6 %: their splats take the same quadrature and, around the peak, the same order
// (fast erred 48 % without them; balanced fell back to exact).
TEST_F(UnseenScenes, PointInsideDenseCloud) { expectWithinBound("unseen_point_inside_dense"); }
// A spot light inside a fog, the camera inside it too: the beam's apex holds most of the image's
// energy. 3.5 % (33 % while the cone was taken at one point per particle: its edges smeared).
// Balanced and fast 3.3 % (fast 28 % while the splats interpolated their camera ray linearly on
// the screen: quads of the particles around the eye took wrong rays, splat_vertex.glsl).
TEST_F(UnseenScenes, SpotInsideFog) { expectWithinBound("unseen_spot_inside"); }
// Meshes and the medium shadowing each other, meshes through the medium, the camera inside it.
TEST_F(UnseenScenes, MeshShadowsMedium) { expectWithinBound("unseen_mesh_shadows_medium"); } // 0.36 %
TEST_F(UnseenScenes, MeshThroughMedium) { expectWithinBound("unseen_mesh_through_medium"); } // 1.3 %
TEST_F(UnseenScenes, CameraInside) { expectWithinBound("unseen_camera_inside"); }            // 0.87 %
// Particle radii from sub-pixel to 2.5 m; a rotated, scaled node; a scene 10^5 m from the origin.
TEST_F(UnseenScenes, RadiusMix) { expectWithinBound("unseen_radius_mix"); }                  // 0.33 %
TEST_F(UnseenScenes, TransformedNode) { expectWithinBound("unseen_transformed_node"); }      // 0.08 %
TEST_F(UnseenScenes, FarFromOrigin) { expectWithinBound("unseen_far_from_origin"); }         // 0.35 %

}  // namespace
}  // namespace nimbus::test::media
