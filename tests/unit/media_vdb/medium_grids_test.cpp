// Tests plugins/participating_media/vdb/src/medium_grids.cpp: the grids written to a file and read
// back with OpenVDB give the closed-form optical depth along rays within the stated error; voxels
// hold the medium at their centres; what varies is a grid and what does not is metadata.
#include "nimbus/media/vdb/medium_grids.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "nimbus/base/error.h"
#include "vdb_rays.h"

namespace nimbus::media::vdb {
namespace {

namespace fs = std::filesystem;

Medium medium(float sigma, const glm::vec3& albedo, const glm::vec3& emission = glm::vec3(0.0f), float g = 0.3f) {
    Medium m;
    m.extinction = sigma;
    m.albedo = albedo;
    m.emission = emission;
    m.g = g;
    return m;
}

// A few particles (overlapping, of different sizes, colours and densities, one emissive, one
// alone) and a rotated constant box of another albedo.
struct SmallScene {
    ParticleSet particles;
    std::vector<Volume> volumes;

    SmallScene() {
        auto add = [&](glm::dvec3 p, float r, float s, const Medium& m) { particles.push(p, r, s, m); };
        add({0.0, 0.0, 0.0}, 1.0f, 3.0f, medium(3.0f, glm::vec3(0.9f)));
        add({0.6, 0.2, -0.1}, 0.5f, 5.0f, medium(5.0f, {0.8f, 0.5f, 0.3f}, {2.0f, 1.0f, 0.0f}));
        add({-0.8, 0.4, 0.3}, 0.7f, 2.0f, medium(2.0f, glm::vec3(0.9f)));
        add({2.5, 0.0, 0.0}, 0.4f, 8.0f, medium(8.0f, glm::vec3(0.9f)));
        add({0.1, -0.9, 0.5}, 0.3f, 10.0f, medium(10.0f, glm::vec3(0.9f)));
        glm::dmat4 world = glm::translate(glm::dmat4(1.0), glm::dvec3(0.2, 0.1, 2.6));
        world = glm::rotate(world, 0.4, glm::dvec3(0.0, 1.0, 0.0));
        world = glm::rotate(world, 0.2, glm::dvec3(1.0, 0.0, 0.0));
        volumes.push_back(makeVolume(VolumeShape::Box, world, glm::dvec3(1.5, 0.8, 1.0), medium(1.5f, glm::vec3(0.6f))));
    }
};

// A folder of its own under the system temp dir, removed afterwards.
class TempDir {
public:
    TempDir() : path_(fs::temp_directory_path() / ("nimbus_vdb_test_" + std::to_string(std::random_device{}()))) { fs::create_directories(path_); }
    ~TempDir() {
        std::error_code ignored;
        fs::remove_all(path_, ignored);
    }
    fs::path operator/(const std::string& name) const { return path_ / name; }

private:
    fs::path path_;
};

struct ReadBack {
    openvdb::FloatGrid::Ptr density;
    openvdb::GridPtrVecPtr grids;
    openvdb::MetaMap::Ptr meta;
    bool has(const std::string& name) const {
        for (const auto& g : *grids)
            if (g->getName() == name) return true;
        return false;
    }
};

ReadBack writeAndRead(const MediumGrids& grids, const fs::path& path) {
    writeVdb(path, grids, {"small_scene", 1.5});
    openvdb::io::File file(path.string());
    file.open();
    ReadBack r;
    r.grids = file.getGrids();
    r.meta = file.getMetadata();
    file.close();
    for (const auto& g : *r.grids)
        if (g->getName() == "density") r.density = openvdb::gridPtrCast<openvdb::FloatGrid>(g);
    return r;
}

TEST(VdbMediumGrids, RoundTripOpticalDepthMatchesTheClosedFormWithinTheStatedError) {
    const SmallScene scene;
    const GridPlan plan = planGrid(scene.particles, scene.volumes);
    ASSERT_TRUE(plan.fits);
    TempDir folder;
    const ReadBack file = writeAndRead(buildMediumGrids(scene.particles, scene.volumes, plan), folder / "small.vdb");
    ASSERT_TRUE(file.density);

    std::mt19937 rng(7);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::vector<std::pair<glm::dvec3, glm::dvec3>> rays;  // origin, unit direction
    for (std::size_t i = 0; i < scene.particles.size(); ++i)  // through each centre and beside it, along each axis
        for (int axis = 0; axis < 3; ++axis)
            for (double offset : {0.0, 0.37, 0.71}) {
                glm::dvec3 dir(0.0), side(0.0);
                dir[axis] = 1.0;
                side[(axis + 1) % 3] = offset * scene.particles.radius[i];
                rays.emplace_back(scene.particles.position[i] + side - 5.0 * dir, dir);
            }
    for (int i = 0; i < 120; ++i) {  // oblique, through the medium's box
        const glm::dvec3 target = plan.bounds.center() + 0.5 * plan.bounds.extent() * glm::dvec3(unit(rng), unit(rng), unit(rng));
        const glm::dvec3 dir = glm::normalize(glm::dvec3(unit(rng), unit(rng), unit(rng)));
        rays.emplace_back(target - 8.0 * dir, dir);
    }
    double worstShare = 0.0, worstRelative = 0.0, worstAbsolute = 0.0;
    for (const auto& [origin, dir] : rays) {
        const double exact = test::closedFormOpticalDepth(scene.particles, scene.volumes, origin, dir, 0.0, 16.0);
        const double read = test::gridOpticalDepth(*file.density, origin, dir, 0.0, 16.0);
        const double bound = test::statedOpticalDepthError(scene.particles, scene.volumes, plan.voxel, origin, dir);
        EXPECT_LE(std::abs(read - exact), bound + 1e-6) << "ray from " << origin.x << " " << origin.y << " " << origin.z << ": exact " << exact;
        if (bound > 0.0) worstShare = std::max(worstShare, std::abs(read - exact) / bound);
        if (exact > 0.1) worstRelative = std::max(worstRelative, std::abs(read - exact) / exact);
        worstAbsolute = std::max(worstAbsolute, std::abs(read - exact));
    }
    std::printf("[ measured] %zu rays, voxel %.4g m: worst |dtau| %.4g, worst relative %.4f (tau > 0.1), worst share of the stated error %.3f\n",
                rays.size(), plan.voxel, worstAbsolute, worstRelative, worstShare);
}

// A constant volume's voxels are σ inside and the share of σ a surface voxel holds, so the grid
// keeps the volume's optical mass (σ × its volume) to the sub-samples' resolution.
TEST(VdbMediumGrids, AConstantVolumeKeepsItsOpticalMass) {
    const SmallScene scene;
    for (const double h : {0.1, 0.05, 0.025}) {
        const MediumGrids grids = buildMediumGrids({}, scene.volumes, planGrid({}, scene.volumes, h));
        double mass = 0.0;
        for (auto it = grids.density->cbeginValueOn(); it; ++it) mass += static_cast<double>(*it) * static_cast<double>(it.getVoxelCount());
        mass *= h * h * h;
        const double exact = 1.5 * 1.5 * 0.8 * 1.0;
        EXPECT_NEAR(mass / exact, 1.0, 1e-3) << "voxel " << h;
        std::printf("[ measured] box of 1.2 m^3 at voxel %.3g m: optical mass %+.2e relative\n", h, mass / exact - 1.0);
    }
}

TEST(VdbMediumGrids, VoxelsHoldTheMediumAtTheirCentres) {
    const SmallScene scene;
    const GridPlan plan = planGrid(scene.particles, {}, 0.07);
    TempDir folder;
    const ReadBack file = writeAndRead(buildMediumGrids(scene.particles, {}, plan), folder / "centres.vdb");
    ASSERT_TRUE(file.density);
    EXPECT_EQ(file.density->transform().voxelSize(), openvdb::Vec3d(0.07));
    std::size_t checked = 0;
    for (auto it = file.density->cbeginValueOn(); it; ++it) {
        ASSERT_TRUE(it.isVoxelValue());
        const openvdb::Vec3d w = file.density->indexToWorld(it.getCoord());
        double sigmaT = 0.0;
        for (std::size_t i = 0; i < scene.particles.size(); ++i) {
            const glm::dvec3 d = glm::dvec3(w.x(), w.y(), w.z()) - scene.particles.position[i];
            sigmaT += scene.particles.sigma[i] * kernelDensity(glm::dot(d, d), scene.particles.radius[i]);
        }
        ASSERT_NEAR(*it, sigmaT, 1e-5 * sigmaT) << it.getCoord();
        ++checked;
    }
    EXPECT_GT(checked, 10000u);
    // And no voxel with medium at its centre is left inactive.
    const openvdb::CoordBBox box = file.density->evalActiveVoxelBoundingBox();
    EXPECT_NEAR(box.min().x() * 0.07, -1.5, 0.07);
    EXPECT_NEAR(box.max().x() * 0.07, 2.9, 0.07);
}

TEST(VdbMediumGrids, WhatVariesIsAGridAndWhatDoesNotIsMetadata) {
    const SmallScene scene;
    const GridPlan plan = planGrid(scene.particles, scene.volumes, 0.05);
    TempDir folder;
    const ReadBack file = writeAndRead(buildMediumGrids(scene.particles, scene.volumes, plan), folder / "attributes.vdb");
    EXPECT_TRUE(file.has("albedo"));
    EXPECT_TRUE(file.has("emission"));
    EXPECT_FALSE(file.has("g")) << "every medium here has g = 0.3";
    EXPECT_FLOAT_EQ(file.density->metaValue<float>("g"), 0.3f);
    EXPECT_EQ(file.density->metaValue<std::string>("phase"), "henyey-greenstein");
    EXPECT_EQ(file.density->getGridClass(), openvdb::GRID_FOG_VOLUME);
    EXPECT_EQ(file.meta->metaValue<std::string>("nimbus_scene"), "small_scene");

    // Where the red particle overlaps the grey one, the albedo is their σ-weighted mean.
    openvdb::Vec3SGrid::Ptr albedo, emission;
    for (const auto& g : *file.grids) {
        if (g->getName() == "albedo") albedo = openvdb::gridPtrCast<openvdb::Vec3SGrid>(g);
        if (g->getName() == "emission") emission = openvdb::gridPtrCast<openvdb::Vec3SGrid>(g);
    }
    ASSERT_TRUE(albedo && emission);
    const openvdb::Coord c(10, 4, -2);  // (0.5, 0.2, -0.1) m
    const glm::dvec3 w(0.5, 0.2, -0.1);
    auto weight = [&](std::size_t i) {
        const glm::dvec3 d = w - scene.particles.position[i];
        return scene.particles.sigma[i] * kernelDensity(glm::dot(d, d), scene.particles.radius[i]);
    };
    const double grey = weight(0), red = weight(1), other = weight(2);
    ASSERT_GT(red, 0.0);
    ASSERT_GT(grey, 0.0);
    const double expected = (0.9 * (grey + other) + 0.5 * red) / (grey + red + other);  // green channel
    EXPECT_NEAR(albedo->tree().getValue(c).y(), expected, 1e-6);
    EXPECT_NEAR(emission->tree().getValue(c).x(), 2.0 * red / (grey + red + other), 1e-6);
    EXPECT_EQ(albedo->activeVoxelCount(), file.density->activeVoxelCount()) << "the attribute grids share density's topology";
    // Inside the box, far from any particle: the box's own albedo.
    const openvdb::Coord inBox = openvdb::Coord::round(openvdb::Vec3d(0.2, 0.1, 2.6) / 0.05);
    EXPECT_FLOAT_EQ(albedo->tree().getValue(inBox).x(), 0.6f);
    EXPECT_FLOAT_EQ(file.density->tree().getValue(inBox), 1.5f);
}

TEST(VdbMediumGrids, AUniformMediumWritesDensityAlone) {
    ParticleSet p;
    for (int i = 0; i < 4; ++i) p.push(glm::dvec3(0.4 * i, 0.0, 0.0), 0.5f, 2.0f, medium(2.0f, {0.7f, 0.8f, 0.9f}, glm::vec3(0.0f), -0.2f));
    TempDir folder;
    const ReadBack file = writeAndRead(buildMediumGrids(p, {}, planGrid(p, {})), folder / "uniform.vdb");
    ASSERT_EQ(file.grids->size(), 1u);
    EXPECT_EQ(file.density->metaValue<openvdb::Vec3s>("albedo"), openvdb::Vec3s(0.7f, 0.8f, 0.9f));
    EXPECT_EQ(file.density->metaValue<openvdb::Vec3s>("emission"), openvdb::Vec3s(0.0f));
    EXPECT_FLOAT_EQ(file.density->metaValue<float>("g"), -0.2f);
}

TEST(VdbMediumGrids, ANoiseVolumeIsItsFieldAtTheVoxelCentres) {
    NoiseField noise;
    noise.kind = NoiseKind::Value;
    noise.octaves = 3;
    noise.frequency = 0.7;
    noise.seed = 5;
    noise.coverage = 0.2;
    noise.falloff = 0.3;
    noise.velocity = glm::dvec3(0.5, 0.0, 0.0);
    const VolumeDesc desc{VolumeShape::Ellipsoid, glm::dvec3(4.0, 2.0, 3.0), noise};
    const std::vector<Volume> volumes{makeVolume(desc, glm::translate(glm::dmat4(1.0), glm::dvec3(1.0, 2.0, 0.0)), medium(2.0f, glm::vec3(0.8f)), "test", 2.0)};
    const GridPlan plan = planGrid({}, volumes, 0.1);
    const MediumGrids grids = buildMediumGrids({}, volumes, plan);
    std::size_t inside = 0;
    for (auto it = grids.density->cbeginValueOn(); it; ++it) {
        for (auto c = it.getBoundingBox().begin(); c; ++c) {  // a tile's voxels too
            const openvdb::Vec3d w = grids.density->indexToWorld(*c);
            const glm::dvec3 p(w.x(), w.y(), w.z());
            const glm::dvec3 u = (p - glm::dvec3(1.0, 2.0, 0.0)) / glm::dvec3(2.0, 1.0, 1.5);
            if (glm::length(u) > 0.85) continue;  // voxels the surface crosses hold a mean instead
            ASSERT_EQ(*it, static_cast<float>(volumeExtinction(volumes[0], p))) << *c;
            ++inside;
        }
    }
    EXPECT_GT(inside, 5000u);
}

TEST(VdbMediumGrids, AnUnwritableFileIsRefusedAndLeavesNothing) {
    const SmallScene scene;
    const MediumGrids grids = buildMediumGrids(scene.particles, {}, planGrid(scene.particles, {}, 0.1));
    TempDir folder;
    const fs::path target = folder / "missing_folder" / "x.vdb";
    try {
        writeVdb(target, grids, {});
        FAIL() << "wrote into a folder that does not exist";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("x.vdb"), std::string::npos) << e.what();
        EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
    }
    EXPECT_FALSE(fs::exists(target.string() + ".part"));
}

}  // namespace
}  // namespace nimbus::media::vdb
