// voxel_light.cpp: a light's irradiance at a point, and its mean over a voxel against the mean
// integrated finely, near a lamp and far from one.
#include "common/voxel_light.h"

#include <gtest/gtest.h>

#include <cmath>

namespace nimbus::media {
namespace {

Light lamp(const glm::dvec3& at) { return Light{.kind = gpu::LightKind::Point, .position = at, .radiance = glm::vec3(1.0f)}; }

// The mean of 1/r² · e^{−σ (r − r_centre)} over the voxel of side h around p, from a lamp at the
// origin, by the midpoint rule on n³ points.
double fineMean(const glm::dvec3& p, double h, double sigma, int n) {
    const double centre = glm::length(p);
    double sum = 0.0;
    for (int k = 0; k < n * n * n; ++k) {
        const glm::dvec3 at(k % n, (k / n) % n, k / (n * n));
        const double r = glm::length(p + ((at + 0.5) / double(n) - 0.5) * h);
        sum += std::exp(-sigma * (r - centre)) / (r * r);
    }
    return sum / (n * n * n);
}

TEST(VoxelLight, ADirectionalLightIsTheCentresTimesItsMeanAcrossTheVoxel) {
    const Light sun{.kind = gpu::LightKind::Directional, .direction = glm::dvec3(0.0, -1.0, 0.0), .radiance = glm::vec3(3.0f)};
    const Arrival a = arrival(sun, glm::dvec3(1.0, 2.0, 3.0));
    EXPECT_EQ(a.irradiance, glm::vec3(3.0f));
    EXPECT_TRUE(std::isinf(a.distance));
    const VoxelLight v = voxelIrradiance(sun, glm::dvec3(1.0, 2.0, 3.0), 0.5, 4.0, a);  // τ across the voxel 2
    EXPECT_EQ(v.irradiance, glm::vec3(3.0f));
    EXPECT_NEAR(v.scale, std::sinh(1.0), 1e-12);
}

// Beside the lamp 1/r² bends across the voxel, and its mean is the voxel's, within 2% of the fine
// integral, through clear and through dense medium; at the lamp's own voxel the centre sees nothing
// and the mean is finite and positive.
TEST(VoxelLight, NearALampTheMeanOverTheVoxelFollowsTheFineIntegral) {
    const double h = 0.5;
    for (const double sigma : {0.0, 2.0})
        for (const glm::dvec3& p : {glm::dvec3(h, 0.0, 0.0), glm::dvec3(h, h, 0.0), glm::dvec3(1.5 * h, 0.5 * h, 0.0)}) {
            const Light l = lamp(glm::dvec3(0.0));
            const VoxelLight v = voxelIrradiance(l, p, h, sigma, arrival(l, p));
            EXPECT_EQ(v.scale, 1.0);
            EXPECT_NEAR(v.irradiance.x / fineMean(p, h, sigma, 64), 1.0, 0.02) << sigma << " " << p.x << " " << p.y;
            EXPECT_GT(v.irradiance.x, arrival(l, p).irradiance.x) << "1/r² is convex: the mean exceeds the centre's";
        }
    const Light l = lamp(glm::dvec3(0.0));
    EXPECT_EQ(arrival(l, glm::dvec3(0.0)).irradiance, glm::vec3(0.0f));
    const VoxelLight own = voxelIrradiance(l, glm::dvec3(0.0), h, 0.0, arrival(l, glm::dvec3(0.0)));
    EXPECT_TRUE(std::isfinite(own.irradiance.x));
    EXPECT_GT(own.irradiance.x, 4.0 / (h * h));
}

// A lamp inside a voxel of optical depth 10⁴ across: the points nearer the lamp than the centre
// see far more light than it, and the mean stays finite (the centre's e^{−τ} brings it down).
TEST(VoxelLight, ALampInAnOpaqueVoxelStaysFinite) {
    const Light l = lamp(glm::dvec3(0.2, 0.0, 0.0));
    const glm::dvec3 p(0.0);
    const VoxelLight v = voxelIrradiance(l, p, 0.5, 2e4, arrival(l, p));
    EXPECT_TRUE(std::isfinite(v.irradiance.x));
    EXPECT_GT(v.irradiance.x, 0.0f);
}

// Two voxels away and more, the centre's value stands (with the mean across the voxel).
TEST(VoxelLight, FarFromALampTheCentreStands) {
    const Light l = lamp(glm::dvec3(0.0));
    const glm::dvec3 p(1.1, 0.0, 0.0);
    const Arrival a = arrival(l, p);
    EXPECT_NEAR(a.irradiance.x, 1.0 / (1.1 * 1.1), 1e-6);
    const VoxelLight v = voxelIrradiance(l, p, 0.5, 0.0, a);
    EXPECT_EQ(v.irradiance, a.irradiance);
    EXPECT_EQ(v.scale, 1.0);
}

}  // namespace
}  // namespace nimbus::media
