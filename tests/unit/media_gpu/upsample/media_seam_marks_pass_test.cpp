// upsample/media_seam_marks_pass.cpp: which particles the seam marks are drawn for. What the
// marks do to a frame is measured in tests/scenes/media/seam_band_test.cpp
// (SeamBand.MixedResolutionRedrawsTheEdgesNearTheWing, with and without mesh_cuts).
#include <gtest/gtest.h>

#include "upsample/media_seam_marks_pass.h"

namespace nimbus::media {
namespace {

// A particle is listed where some mesh box enters its sphere, by index, in order; a box beside
// every sphere, or no mesh, lists none (the pass then draws nothing).
TEST(ParticlesCutByMeshes, ListsTheParticlesWhoseSphereAMeshBoxEnters) {
    ParticleSet particles;
    particles.push({0.0, 0.0, 0.0}, 1.0f, 1.0f, Medium{});  // the box's face passes 0.5 m inside it
    particles.push({5.0, 0.0, 0.0}, 1.0f, 1.0f, Medium{});  // its sphere ends 0.5 m short of the box
    particles.push({2.0, 0.0, 0.0}, 0.5f, 1.0f, Medium{});  // inside the box
    OccluderBox box;
    box.centre = {2.0, 0.0, 0.0};
    box.half = {1.5, 1.5, 1.5};
    EXPECT_EQ(particlesCutByMeshes({box}, particles), (std::vector<std::uint32_t>{0, 2}));
    EXPECT_TRUE(particlesCutByMeshes({}, particles).empty());
    box.centre = {-10.0, 0.0, 0.0};
    EXPECT_TRUE(particlesCutByMeshes({box}, particles).empty());
}

}  // namespace
}  // namespace nimbus::media
