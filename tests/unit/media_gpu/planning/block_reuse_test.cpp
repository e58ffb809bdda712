// Tests plugins/participating_media/core/src/planning/block_reuse.cpp: when an earlier frame's
// camera tiles may be read again (the verdicts), and that the rewritten tiles send a pixel's NDC
// to the texel the earlier view rendered for the same point.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "block_test_clouds.h"
#include "nimbus/gpu/view.h"
#include "planning/block_reuse.h"

namespace nimbus::media {
namespace {

constexpr int kWidth = 160, kHeight = 120;

Block blockAt(const glm::dvec3& centre, double radius) {
    Block b;
    b.centre = centre;
    b.radius = radius;
    b.meanParticleRadius = static_cast<float>(radius / 4.0);
    b.count = 16;
    return b;
}

// Two blocks about the origin, in view of a camera 10 m away.
BlockPartition twoBlocks() {
    BlockPartition partition;
    partition.blocks.push_back(blockAt(glm::dvec3(-1.0, 0.0, 0.0), 0.8));
    partition.blocks.push_back(blockAt(glm::dvec3(1.2, 0.3, 0.5), 0.6));
    return partition;
}

struct Frame {
    gpu::View camera;
    WorldView world;
    BlockViewPlan plan;
};

// The camera on a circle of radius `distance` about the y axis, `degrees` round from +z, looking
// at `target`.
Frame frameAt(const BlockPartition& partition, double degrees, double distance = 10.0, const glm::dvec3& target = glm::dvec3(0.0)) {
    const double a = glm::radians(degrees);
    const glm::dvec3 eye(distance * std::sin(a), 0.0, distance * std::cos(a));
    Frame f;
    f.camera = test::makeView(test::lookAtCamera(eye, target), kWidth, kHeight);
    f.world = {.origin = f.camera.origin,
               .viewProjection = glm::dmat4(f.camera.viewProjection),
               .forward = f.camera.forward,
               .perspective = true,
               .znear = f.camera.znear};
    f.plan = planBlockView(partition, {f.camera.view, f.camera.viewProjection, true, glm::vec3(0.0f), f.camera.znear, glm::ivec2(kWidth, kHeight)},
                           f.camera.origin, 0.5f, 4096);
    return f;
}

glm::dvec2 ndcOf(const Frame& f, const glm::dvec3& world) {
    const glm::dvec4 clip = glm::dmat4(f.camera.viewProjection) * glm::dvec4(world - f.camera.origin, 1.0);
    return glm::dvec2(clip) / clip.w;
}

// block_data.glsl tileTexel, for both kinds of tile.
glm::dvec2 tileTexel(const GpuBlockTile& tile, const glm::dvec2& ndc) {
    if (tile.reproject[0].w > 0.5f) {
        const glm::dvec3 p(ndc, 1.0);
        return glm::dvec2(glm::dot(glm::dvec3(tile.reproject[0]), p), glm::dot(glm::dvec3(tile.reproject[1]), p)) /
               glm::dot(glm::dvec3(tile.reproject[2]), p);
    }
    const glm::dvec2 local = (ndc - glm::dvec2(tile.rect.x, tile.rect.y)) / glm::dvec2(tile.rect.z - tile.rect.x, tile.rect.w - tile.rect.y);
    return glm::dvec2(tile.atlas.x, tile.atlas.y) + local * glm::dvec2(tile.atlas.z, tile.atlas.w);
}

TEST(ReuseCameraTiles, ASmallOrbitReadsTheSamePointsTexel) {
    const BlockPartition partition = twoBlocks();
    const Frame then = frameAt(partition, 0.0);
    Frame now = frameAt(partition, 1.0);
    ASSERT_EQ(reuseCameraTiles(partition, then.plan, then.world, now.world, {.degrees = 2.0}, now.plan), ReuseVerdict::Reused);
    EXPECT_EQ(now.plan.atlasSize, then.plan.atlasSize);
    for (std::size_t b = 0; b < partition.blocks.size(); ++b) {
        const GpuBlockTile& tile = now.plan.tiles[b];
        EXPECT_EQ(tile.atlas, then.plan.tiles[b].atlas) << b;
        EXPECT_EQ(tile.instance.y, 0.0f) << b << ": read bilinearly";
        const double shift = glm::length(partition.blocks[b].centre - now.camera.origin) - glm::length(partition.blocks[b].centre - then.camera.origin);
        EXPECT_NEAR(tile.instance.x, shift, 1e-5) << b;
        // The block's centre, and a point beside it at its depth in the new view, fall where the
        // old view put them in the old tile (exactly at that depth: the map is the plane's).
        const glm::dvec3 centre = partition.blocks[b].centre;
        const glm::dvec3 beside = centre + 0.3 * now.camera.right + 0.2 * now.camera.up;
        for (const glm::dvec3& p : {centre, beside}) {
            const glm::dvec2 expected = tileTexel(then.plan.tiles[b], ndcOf(then, p));
            const glm::dvec2 got = tileTexel(tile, ndcOf(now, p));
            EXPECT_NEAR(got.x, expected.x, 1e-3) << b;
            EXPECT_NEAR(got.y, expected.y, 1e-3) << b;
        }
    }
}

TEST(ReuseCameraTiles, TheSameViewKeepsItsTilesAsTheyAre) {
    const BlockPartition partition = twoBlocks();
    const Frame then = frameAt(partition, 0.0);
    Frame now = frameAt(partition, 0.0);
    ASSERT_EQ(reuseCameraTiles(partition, then.plan, then.world, now.world, {.degrees = 2.0}, now.plan), ReuseVerdict::Reused);
    for (std::size_t b = 0; b < partition.blocks.size(); ++b) {
        EXPECT_EQ(now.plan.tiles[b].reproject[0].w, 0.0f) << b;
        EXPECT_EQ(now.plan.tiles[b].atlas, then.plan.tiles[b].atlas) << b;
    }
}

TEST(ReuseCameraTiles, EachLimitEndsIt) {
    const BlockPartition partition = twoBlocks();
    const Frame then = frameAt(partition, 0.0);
    auto verdict = [&](Frame now, double degrees) { return reuseCameraTiles(partition, then.plan, then.world, now.world, {.degrees = degrees}, now.plan); };
    EXPECT_EQ(verdict(frameAt(partition, 3.0), 2.0), ReuseVerdict::Turned);
    EXPECT_EQ(verdict(frameAt(partition, 1.0), 0.0), ReuseVerdict::Turned) << "0 degrees: never";
    EXPECT_EQ(verdict(frameAt(partition, 0.0, 8.0), 2.0), ReuseVerdict::Scaled) << "10 m to 8 m: 25% larger";
    EXPECT_EQ(verdict(frameAt(partition, 0.0, 9.5), 2.0), ReuseVerdict::Reused) << "10 m to 9.5 m: 5% larger";
    EXPECT_EQ(verdict(frameAt(partition, 0.0, 0.9), 90.0), ReuseVerdict::NearPlane) << "the second block reaches the eye";
    // The camera looks away to the side: a block enters from the edge where its old tile was clipped.
    const Frame edge = frameAt(partition, 0.0, 10.0, glm::dvec3(-4.5, 0.0, 0.0));
    Frame back = frameAt(partition, 0.0, 10.0, glm::dvec3(-4.0, 0.0, 0.0));
    EXPECT_EQ(reuseCameraTiles(partition, edge.plan, edge.world, back.world, {.degrees = 2.0}, back.plan), ReuseVerdict::Uncovered);
}

TEST(ReuseCameraTiles, APureTurnKeepsEveryDirection) {
    const BlockPartition partition = twoBlocks();
    const Frame then = frameAt(partition, 0.0);
    Frame now = frameAt(partition, 0.0, 10.0, glm::dvec3(0.2, 0.1, 0.0));  // the eye stays; the view turns
    EXPECT_EQ(reuseCameraTiles(partition, then.plan, then.world, now.world, {.degrees = 0.01}, now.plan), ReuseVerdict::Reused);
}

}  // namespace
}  // namespace nimbus::media
