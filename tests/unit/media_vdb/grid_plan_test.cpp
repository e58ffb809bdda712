// Tests plugins/participating_media/vdb/src/grid_plan.cpp: the automatic voxel, the voxel cap, the
// 32-bit index range, and the stated interpolation error of a lone particle.
#include "nimbus/media/vdb/grid_plan.h"

#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "nimbus/media/vdb/medium_grids.h"
#include "vdb_rays.h"

namespace nimbus::media::vdb {
namespace {

ParticleSet cloud(int n, float radius, const glm::dvec3& offset = glm::dvec3(0.0)) {
    ParticleSet p;
    Medium m;
    m.extinction = 2.0f;
    for (int i = 0; i < n; ++i) p.push(offset + glm::dvec3(0.3 * i, 0.1 * (i % 3), 0.0), radius, 2.0f, m);
    return p;
}

TEST(VdbGridPlan, AutomaticVoxelIsASixthOfTheSmallParticlesRadius) {
    const GridPlan plan = planGrid(cloud(20, 0.6f), {});
    EXPECT_TRUE(plan.fits);
    EXPECT_TRUE(plan.automatic);
    EXPECT_FALSE(plan.coarsened);
    EXPECT_NEAR(plan.voxel, 0.1, 1e-7);  // radius 0.6f
    EXPECT_LE(plan.estimatedVoxels, plan.boxVoxels);
}

TEST(VdbGridPlan, AVolumeAsksForAThirtySecondOfItsThinnestSide) {
    Medium m;
    const glm::dmat4 world = glm::scale(glm::translate(glm::dmat4(1.0), glm::dvec3(1, 2, 3)), glm::dvec3(2.0, 1.0, 1.0));
    const std::vector<Volume> volumes{makeVolume(VolumeShape::Box, world, glm::dvec3(1.0, 0.64, 3.0), m)};
    const GridPlan plan = planGrid({}, volumes);
    EXPECT_TRUE(plan.fits);
    EXPECT_NEAR(plan.voxel, 0.02, 1e-12);
}

TEST(VdbGridPlan, ATooSmallVoxelDoesNotFitAndNamesTheSmallestThatDoes) {
    const ParticleSet particles = cloud(50, 1.0f);
    const GridPlan tiny = planGrid(particles, {}, 1e-4);
    EXPECT_FALSE(tiny.fits);
    EXPECT_GT(tiny.estimatedVoxels, kMaxVoxels);
    EXPECT_GT(tiny.smallestVoxel, 1e-4);
    const GridPlan smallest = planGrid(particles, {}, tiny.smallestVoxel);
    EXPECT_TRUE(smallest.fits);
    EXPECT_LE(smallest.estimatedVoxels, kMaxVoxels);
    EXPECT_GT(smallest.estimatedVoxels, 0.9 * kMaxVoxels) << "the smallest that fits, not merely one that does";
    EXPECT_FALSE(planGrid(particles, {}, 0.98 * tiny.smallestVoxel).fits);
}

TEST(VdbGridPlan, AnAutomaticVoxelIsCoarsenedRatherThanRefused) {
    // Tiny sparks among large puffs over 100 m: a sixth of the sparks' radius would need ~10¹¹ voxels.
    ParticleSet p;
    Medium m;
    for (int i = 0; i < 1000; ++i) p.push(glm::dvec3(0.1 * i, 0.37 * (i % 17), 0.0), i % 5 == 0 ? 0.01f : 1.0f, 1.0f, m);
    const GridPlan plan = planGrid(p, {});
    EXPECT_TRUE(plan.fits);
    EXPECT_TRUE(plan.coarsened);
    EXPECT_LE(plan.estimatedVoxels, kAutoVoxels);
    EXPECT_GT(plan.estimatedVoxels, 0.9 * kAutoVoxels);
    EXPECT_GT(plan.voxel, 0.01 / 6.0);
}

TEST(VdbGridPlan, OverlapsDoNotInflateTheEstimate) {
    // A thousand particles on one spot: the union is one sphere, not a thousand.
    ParticleSet p;
    Medium m;
    for (int i = 0; i < 1000; ++i) p.push(glm::dvec3(1e-3 * i, 0.0, 0.0), 1.0f, 1.0f, m);
    const GridPlan plan = planGrid(p, {}, 0.05);
    EXPECT_LT(plan.estimatedVoxels, 3.0 * plan.boxVoxels);
    EXPECT_LE(plan.estimatedVoxels, plan.boxVoxels);
}

TEST(VdbGridPlan, FarFromTheOriginTheIndexRangeLimitsTheVoxel) {
    const ParticleSet far = cloud(3, 0.01f, glm::dvec3(5e6, 0.0, 0.0));
    EXPECT_TRUE(planGrid(far, {}, 0.1).fits);
    const GridPlan tooFine = planGrid(far, {}, 1e-3);  // 5·10⁹ voxels from the origin: beyond 32-bit indices
    EXPECT_FALSE(tooFine.fits);
    EXPECT_LT(tooFine.estimatedVoxels, kMaxVoxels) << "refused for the index range, not the count";
    EXPECT_GE(tooFine.smallestVoxel, 5e6 / kMaxIndex);
}

TEST(VdbGridPlan, AnEmptyMediumHasNoPlan) {
    const GridPlan plan = planGrid({}, {});
    EXPECT_FALSE(plan.fits);
    EXPECT_TRUE(plan.bounds.empty());
}

// The stated error (kernelError) is what a lone particle shows: the worst ray is the one midway
// between centre lines, where linear interpolation flattens the peak across both perpendicular
// axes. Measured over rays along an axis at every quarter voxel across the particle.
TEST(VdbGridPlan, KernelErrorIsTheWorstErrorOfALoneParticle) {
    for (const double perRadius : {3.0, 6.0, 9.0}) {
        const double radius = 1.0, h = radius / perRadius, sigma = 2.0;
        ParticleSet p;
        p.push(glm::dvec3(0.31 * h, -0.17 * h, 0.4 * h), static_cast<float>(radius), static_cast<float>(sigma), Medium{});
        const GridPlan plan = planGrid(p, {}, h);
        const MediumGrids grids = buildMediumGrids(p, {}, plan);
        const double centreDepth = particleOpticalDepth(sigma, radius, 0.0, -radius, radius);
        double worst = 0.0;
        for (double y = -1.0; y <= 1.0; y += h / 4.0)
            for (double z = -1.0; z <= 1.0; z += h / 4.0) {
                const glm::dvec3 origin(-3.0, y, z), dir(1.0, 0.0, 0.0);
                const double exact = test::closedFormOpticalDepth(p, {}, origin, dir, 0.0, 6.0);
                worst = std::max(worst, std::abs(test::gridOpticalDepth(*grids.density, origin, dir, 0.0, 6.0) - exact) / centreDepth);
            }
        SCOPED_TRACE("voxel R/" + std::to_string(perRadius));
        EXPECT_LE(worst, kernelError(h, radius));
        EXPECT_GE(worst, 0.6 * kernelError(h, radius)) << "the bound is the real size of the error, not a loose one";
        std::printf("[ stated  ] lone particle, voxel R/%g: worst |dtau| %.4f of the centre depth, stated %.4f\n", perRadius, worst,
                    kernelError(h, radius));
    }
}

}  // namespace
}  // namespace nimbus::media::vdb
