// Tests plugins/participating_media/core/src/block_composite_pass.cpp blocksNearMeshes: which blocks
// are composited with the exact cut through their own particles (a mesh may pass among them).
#include <gtest/gtest.h>

#include <cmath>

#include "block_passes.h"

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
MeshBox tiltedPlate() {
    MeshBox box;
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
    MeshBox ground;
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

}  // namespace
}  // namespace nimbus::media
