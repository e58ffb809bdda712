#include "raymarch/voxel_grid.h"

#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace nimbus::media {
namespace {

ParticleSet oneParticle(const glm::dvec3& at, float radius, float sigma) {
    ParticleSet p;
    Medium m;
    m.albedo = glm::vec3(0.5f, 0.6f, 0.7f);
    m.emission = glm::vec3(0.2f, 0.0f, 0.0f);
    m.g = 0.4f;
    p.push(at, radius, sigma, m);
    return p;
}

std::size_t index(const VoxelGrid& g, int x, int y, int z) {
    return (static_cast<std::size_t>(z) * static_cast<std::size_t>(g.size.y) + static_cast<std::size_t>(y)) *
               static_cast<std::size_t>(g.size.x) + static_cast<std::size_t>(x);
}

TEST(VoxelGrid, VoxelCentresHoldTheKernel) {
    const VoxelGrid g = voxelize(oneParticle({1e5, 2.0, -3.0}, 0.9f, 4.0f), {}, 18);  // far from the origin on purpose
    ASSERT_FALSE(g.empty());
    double maxSigma = 0.0, mass = 0.0;
    for (int z = 0; z < g.size.z; ++z)
        for (int y = 0; y < g.size.y; ++y)
            for (int x = 0; x < g.size.x; ++x) {
                const glm::vec4 s = g.scattering[index(g, x, y, z)], e = g.emission[index(g, x, y, z)];
                const glm::dvec3 centre = g.min + (glm::dvec3(x, y, z) + 0.5) * g.voxel;
                const double r = glm::length(centre - glm::dvec3(1e5, 2.0, -3.0)) / 0.9;
                const double expected = r < 1.0 ? 4.0 * std::exp(-4.5 * r * r) : 0.0;
                EXPECT_NEAR(s.w, expected, 1e-5) << x << "," << y << "," << z;
                EXPECT_NEAR(s.x, 0.5 * s.w, 1e-5);
                EXPECT_NEAR(e.x, 0.2 * s.w, 1e-5);
                EXPECT_NEAR(e.w, 0.4 * s.w, 1e-5);
                maxSigma = std::max(maxSigma, static_cast<double>(s.w));
                mass += s.w * g.voxel.x * g.voxel.y * g.voxel.z;
            }
    EXPECT_GT(maxSigma, 3.5);
    // ∫σρ dV of the truncated kernel: σ·(2π/9)^{3/2}·R³·(erf(√4.5)³-ish) ≈ 0.9735 σ (√(2π)s)³ with s = R/3.
    const double s = 0.9 / 3.0, full = 4.0 * std::pow(std::sqrt(2.0 * M_PI) * s, 3.0);
    EXPECT_NEAR(mass / full, 0.97, 0.03);
}

TEST(VoxelGrid, APaddingVoxelSurroundsTheSpheres) {
    const VoxelGrid g = voxelize(oneParticle({0.0, 0.0, 0.0}, 1.0f, 1.0f), {}, 0);
    for (int y = 0; y < g.size.y; ++y)
        for (int x = 0; x < g.size.x; ++x) {
            EXPECT_EQ(g.scattering[index(g, x, y, 0)].w, 0.0f);
            EXPECT_EQ(g.scattering[index(g, x, y, g.size.z - 1)].w, 0.0f);
        }
    EXPECT_NEAR(g.voxel.x, 1.0 / 3.0, 1e-12);  // a third of the radius when nothing is asked
}

TEST(VoxelGrid, AutomaticSizeIsCappedAndEmptyInputGivesNoGrid) {
    ParticleSet p = oneParticle({0.0, 0.0, 0.0}, 0.01f, 1.0f);
    Medium m;
    p.push({500.0, 0.0, 0.0}, 0.01f, 1.0f, m);
    const VoxelGrid g = voxelize(p, {}, 0);
    EXPECT_LE(std::max({g.size.x, g.size.y, g.size.z}), kMaxAutoVoxels + 2);
    EXPECT_TRUE(voxelize(ParticleSet{}, {}, 0).empty());
}

// A volume adds σ times the share of each voxel it covers: whole voxels inside hold σ, and the sum
// over the grid is σ times the volume's size, even where its faces fall between voxel centres.
TEST(VoxelGrid, VolumesAddTheirCoveredShare) {
    Medium m;
    m.albedo = glm::vec3(0.25f, 0.5f, 1.0f);
    m.g = 0.5f;
    const glm::dmat4 world = glm::translate(glm::dmat4(1.0), glm::dvec3(1e4, 0.3, -2.0));  // far from the origin on purpose
    const Volume box = makeVolume(VolumeShape::Box, world, {2.0, 1.0, 1.5}, m);
    const VoxelGrid g = voxelize(ParticleSet{}, {box}, 40);
    EXPECT_NEAR(g.voxel.x, 2.0 / 40.0, 1e-12);
    double sum = 0.0;
    for (const glm::vec4& v : g.scattering) sum += v.w;
    const double voxelVolume = g.voxel.x * g.voxel.y * g.voxel.z;
    EXPECT_NEAR(sum * voxelVolume, box.sigma() * 2.0 * 1.0 * 1.5, 0.01 * box.sigma() * 3.0);  // 4³ sub-samples on the faces
    const glm::ivec3 centre = glm::ivec3((glm::dvec3(1e4, 0.3, -2.0) - g.min) / g.voxel.x);
    const std::size_t v = index(g, centre.x, centre.y, centre.z);
    EXPECT_FLOAT_EQ(g.scattering[v].w, box.medium.extinction);
    EXPECT_FLOAT_EQ(g.scattering[v].x, 0.25f * box.medium.extinction);
    EXPECT_FLOAT_EQ(g.emission[v].w, 0.5f * box.medium.extinction);
    EXPECT_FALSE(g.rayleigh);
}

}  // namespace
}  // namespace nimbus::media
