// Tests plugins/participating_media/core/src/planning/block_classification.cpp: which blocks are composited
// with the exact cut through their own particles (blocksNearMeshes: a mesh may pass among them),
// which are shaded from their own particles (blocksOfUnresolvedParticles: the light slices do
// not resolve them), and which exactly (blocksShadedExactly: a mesh is seen in the medium there).
#include <gtest/gtest.h>

#include <cmath>

#include "planning/block_classification.h"
#include "block_test_clouds.h"
#include "nimbus/gpu/view.h"

namespace nimbus::media {
namespace {

Block blockAt(const glm::dvec3& centre, double radius, float meanParticleRadius) {
    Block b;
    b.centre = centre;
    b.radius = radius;
    b.meanParticleRadius = meanParticleRadius;
    b.count = 1;
    return b;
}

// A square plate 4 m wide and 2 cm thick through the origin, tilted 45° about z.
OccluderBox tiltedPlate() {
    OccluderBox box;
    const double c = std::sqrt(0.5);
    box.axis[0] = glm::dvec3(c, c, 0.0);
    box.axis[1] = glm::dvec3(-c, c, 0.0);
    box.axis[2] = glm::dvec3(0.0, 0.0, 1.0);
    box.half = glm::dvec3(2.0, 0.01, 2.0);
    return box;
}

TEST(BlocksNearMeshes, TheOrientedBoxDecidesNotItsAxisAlignedHull) {
    BlockPartition partition;
    // (1, −1, 0) lies 1.41 m off the plate's plane but inside its axis-aligned hull (±1.41 in x, y).
    partition.blocks.push_back(blockAt(glm::dvec3(1.0, -1.0, 0.0), 0.8, 0.2f));
    // The same distance on the plate's normal, with a sphere that reaches it.
    partition.blocks.push_back(blockAt(glm::dvec3(1.0, -1.0, 0.0), 1.3, 0.2f));
    // Beside the plate's edge, 0.5 m past it in z.
    partition.blocks.push_back(blockAt(glm::dvec3(0.0, 0.0, 2.5), 0.4, 0.2f));
    const std::vector<std::uint8_t> near = blocksNearMeshes(partition, {tiltedPlate()});
    ASSERT_EQ(near.size(), 3u);
    EXPECT_EQ(near[0], 0) << "1.41 m from the plate, reach 1.0 m";
    EXPECT_EQ(near[1], 1) << "1.41 m from the plate, reach 1.5 m";
    EXPECT_EQ(near[2], 1) << "0.5 m past the edge, reach 0.6 m";
}

TEST(BlocksNearMeshes, ReachAddsTheMeanParticleRadius) {
    // The cut in block_composite.frag reaches kernel tails past the block's sphere.
    BlockPartition partition;
    partition.blocks.push_back(blockAt(glm::dvec3(0.0, 3.0, 0.0), 2.5, 0.6f));  // 0.5 m short, reach 0.6 m further
    partition.blocks.push_back(blockAt(glm::dvec3(0.0, 3.0, 0.0), 2.5, 0.4f));  // 0.5 m short, 0.4 m further: misses
    OccluderBox ground;
    ground.half = glm::dvec3(20.0, 0.0, 20.0);  // a plane at y = 0
    const std::vector<std::uint8_t> near = blocksNearMeshes(partition, {ground});
    EXPECT_EQ(near[0], 1);
    EXPECT_EQ(near[1], 0);
}

TEST(BlocksNearMeshes, NoMeshesNoExactCut) {
    BlockPartition partition;
    partition.blocks.push_back(blockAt(glm::dvec3(0.0), 1.0, 0.5f));
    EXPECT_EQ(blocksNearMeshes(partition, {}), std::vector<std::uint8_t>{0});
}

// An orthographic light view looking down −Z from z = 0: slices between depths 0 and 8, 256 texels
// over 8 m (3.1 cm per texel).
gpu::GpuLightView sunView(float slices) {
    gpu::LightView view;
    view.depthNear = 0.0f;
    view.depthFar = 8.0f;
    view.halfExtent = glm::vec2(4.0f);
    return gpu::packLightView(view, 0, slices, 256.0f);
}

// One block per particle of `radii` and `sigmas`, all at (0, 0, −4).
struct OneParticleBlocks {
    ParticleSet particles;
    BlockPartition partition;
};

OneParticleBlocks oneParticleBlocks(const std::vector<float>& radii, const std::vector<float>& sigmas) {
    OneParticleBlocks out;
    for (std::size_t i = 0; i < radii.size(); ++i) {
        out.particles.push(glm::dvec3(0.0, 0.0, -4.0), radii[i], sigmas[i], Medium{});
        Block b = blockAt(glm::dvec3(0.0, 0.0, -4.0), radii[i], radii[i]);
        b.first = static_cast<std::uint32_t>(i);
        out.partition.blocks.push_back(b);
        out.partition.order.push_back(static_cast<std::uint32_t>(i));
    }
    return out;
}

TEST(BlocksOfUnresolvedParticles, ParticlesThinnerThanTheSliceSpacingOrATexelOrTooDenseForThem) {
    // 32 slices over 8 m: planes 25 cm apart; texels 3.1 cm.
    const OneParticleBlocks b = oneParticleBlocks({0.2f, 0.1f, 0.006f, 0.2f}, {1.0f, 1.0f, 1.0f, 10.0f});
    const std::vector<std::uint8_t> own = blocksOfUnresolvedParticles(b.partition, b.particles, {sunView(32.0f)}, glm::dvec3(0.0));
    EXPECT_EQ(own, (std::vector<std::uint8_t>{0, 1, 1, 1})) << "resolved; planes wider than it; texels too; τ 2.5 per interval";
    EXPECT_EQ(blocksOfUnresolvedParticles(b.partition, b.particles, {}, glm::dvec3(0.0)), (std::vector<std::uint8_t>{0, 0, 0, 0}))
        << "no light views";
}

TEST(BlocksOfUnresolvedParticles, TooManyParticlesToWalkKeepTheSlices) {
    OneParticleBlocks b = oneParticleBlocks({0.006f}, {1.0f});
    for (std::uint32_t k = 1; k <= kMaxOwnShadedBlockParticles; ++k) {
        b.particles.push(glm::dvec3(0.0, 0.0, -4.0), 0.006f, 1.0f, Medium{});
        b.partition.order.push_back(k);
    }
    b.partition.blocks[0].count = kMaxOwnShadedBlockParticles + 1;
    EXPECT_EQ(blocksOfUnresolvedParticles(b.partition, b.particles, {sunView(32.0f)}, glm::dvec3(0.0)), std::vector<std::uint8_t>{0});
}

TEST(BlocksOfUnresolvedParticles, AnyViewThatDoesNotResolveThemDecides) {
    const OneParticleBlocks b = oneParticleBlocks({0.2f}, {1.0f});
    EXPECT_EQ(blocksOfUnresolvedParticles(b.partition, b.particles, {sunView(32.0f)}, glm::dvec3(0.0)), std::vector<std::uint8_t>{0});
    EXPECT_EQ(blocksOfUnresolvedParticles(b.partition, b.particles, {sunView(32.0f), sunView(4.0f)}, glm::dvec3(0.0)),
              std::vector<std::uint8_t>{1})
        << "4 slices over 8 m are 2 m apart";
}

// The camera at z = 10 looks down −z at a plate 2 m wide, 4 cm thick, at the origin (facing it).
struct PlateView {
    gpu::View view = test::makeView(test::lookAtCamera(glm::dvec3(0.0, 0.0, 10.0), glm::dvec3(0.0)), 160, 120);
    OccluderBox plate;
    PlateView() { plate.half = glm::dvec3(1.0, 1.0, 0.02); }
};

TEST(BlocksShadedExactly, NearAMeshOrInFrontOfOneAmongTheBlocks) {
    const PlateView scene;
    BlockPartition partition;
    partition.blocks.push_back(blockAt(glm::dvec3(0.5, 0.0, 0.3), 0.5, 0.2f));   // through the plate
    partition.blocks.push_back(blockAt(glm::dvec3(0.0, 0.3, 4.0), 0.5, 0.2f));   // between the eye and the plate
    partition.blocks.push_back(blockAt(glm::dvec3(2.0, 0.0, 4.0), 0.5, 0.2f));   // in front, but beside it on the screen
    partition.blocks.push_back(blockAt(glm::dvec3(0.0, 0.0, -4.0), 0.5, 0.2f));  // behind it
    partition.blocks.push_back(blockAt(glm::dvec3(6.0, 0.0, 4.0), 0.5, 0.2f));   // off the screen
    const BlockViewPlan plan = planBlockView(partition, ImpostorView{scene.view.view, scene.view.viewProjection, true, glm::vec3(0.0f),
                                                                     scene.view.znear, glm::ivec2(160, 120)},
                                             scene.view.origin, 1.0f, 2048);
    EXPECT_EQ(blocksShadedExactly(partition, {scene.plate}, plan, scene.view), (std::vector<std::uint8_t>{1, 1, 0, 0, 0}));
}

TEST(BlocksShadedExactly, AMeshAmongNoBlockShadesNoneExactly) {
    const PlateView scene;
    BlockPartition partition;
    partition.blocks.push_back(blockAt(glm::dvec3(0.0, 0.3, 4.0), 0.5, 0.2f));  // in front of the plate, far from it
    const BlockViewPlan plan = planBlockView(partition, ImpostorView{scene.view.view, scene.view.viewProjection, true, glm::vec3(0.0f),
                                                                     scene.view.znear, glm::ivec2(160, 120)},
                                             scene.view.origin, 1.0f, 2048);
    EXPECT_EQ(blocksShadedExactly(partition, {scene.plate}, plan, scene.view), std::vector<std::uint8_t>{0})
        << "a ground under a cloud is seen behind every block, and passes among none";
    EXPECT_EQ(blocksShadedExactly(partition, {}, plan, scene.view), std::vector<std::uint8_t>{0});
}

}  // namespace
}  // namespace nimbus::media
