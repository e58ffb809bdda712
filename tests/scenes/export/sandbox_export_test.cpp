// `sandbox export` run as a user runs it: every bad argument is refused in one line with exit code
// 2 and no file; a scene of particles and a box round-trips through the .vdb (read back with
// OpenVDB) within the stated error of the closed form; a content scene's emitters export with the
// mass of the particles the renderers draw.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <random>

#include <openvdb/openvdb.h>

#include "nimbus/media/ecs/media_plugin.h"
#include "nimbus/media/optics.h"
#include "process.h"
#include "session.h"
#include "vdb_rays.h"

namespace nimbus::test {
namespace {

namespace fs = std::filesystem;

const fs::path kData = NIMBUS_TEST_DATA_DIR;
const fs::path kContent = NIMBUS_CONTENT_DIR_FOR_TESTS;

ProcessResult sandbox(const std::vector<std::string>& args) { return runProcess(sandboxExecutable(), args); }

TEST(SandboxExport, RefusesBadArgumentsInOneLine) {
    TempFolder out;
    const std::string scene = (kData / "volume_scenes/mixed.gltf").string(), vdb = (out / "x.vdb").string();
    struct Case {
        std::vector<std::string> args;
        std::string names;  // what the line must mention
    };
    const std::vector<Case> cases = {
        {{"export"}, "scene"},
        {{"export", scene}, "--out"},
        {{"export", scene, "--out", vdb, "--size", "64x64"}, "--size"},
        {{"export", scene, "second.gltf", "--out", vdb}, "second.gltf"},
        {{"export", scene, "--out", (out / "x.exr").string()}, ".vdb"},
        {{"export", scene, "--out", (out / "x").string()}, ".vdb"},
        {{"export", scene, "--out", (out / "no_folder/x.vdb").string()}, "does not exist"},
        {{"export", scene, "--out", vdb, "--voxel", "0"}, "--voxel"},
        {{"export", scene, "--out", vdb, "--voxel", "-0.1"}, "--voxel"},
        {{"export", scene, "--out", vdb, "--voxel", "nan"}, "--voxel"},
        {{"export", scene, "--out", vdb, "--voxel", "inf"}, "--voxel"},
        {{"export", scene, "--out", vdb, "--voxel", "0.1m"}, "--voxel"},
        {{"export", scene, "--out", vdb, "--voxel", "1e-7"}, "too small"},
        {{"export", scene, "--out", vdb, "--time", "-1"}, "--time"},
        {{"export", scene, "--out", vdb, "--time", "nan"}, "--time"},
        {{"export", scene, "--out", vdb, "--time", "inf"}, "--time"},
        {{"export", scene, "--out", vdb, "--time", "two"}, "--time"},
        {{"export", (kData / "khronos/Box/Box.gltf").string(), "--out", vdb}, "no medium"},
        {{"export", (kContent / "scenes/smoke.gltf").string(), "--out", vdb, "--time", "0"}, "no medium"},
        {{"export", (kData / "no_such_scene.gltf").string(), "--out", vdb}, "no_such_scene.gltf"},
        {{"export", (kData / "malformed/bad_background.gltf").string(), "--out", vdb}, "bad_background.gltf"},
    };
    for (const Case& c : cases) {
        std::string line;
        for (const auto& a : c.args) line += a + " ";
        SCOPED_TRACE(line);
        const ProcessResult r = sandbox(c.args);
        EXPECT_FALSE(r.signaled) << explain(r);
        EXPECT_EQ(r.exitCode, 2) << explain(r);
        const std::vector<std::string> lines = r.errLines();
        ASSERT_EQ(lines.size(), 1u) << explain(r);
        EXPECT_EQ(lines[0].rfind("sandbox: ", 0), 0u) << lines[0];
        EXPECT_NE(lines[0].find(c.names), std::string::npos) << lines[0];
        EXPECT_TRUE(r.out.empty()) << r.out;
        EXPECT_TRUE(fs::is_empty(out.path())) << "a refused export writes nothing";
    }
}

struct Exported {
    ProcessResult process;
    openvdb::GridPtrVecPtr grids;
    openvdb::FloatGrid::Ptr density;
    std::uintmax_t bytes = 0;
};

Exported exportScene(const fs::path& scene, const fs::path& vdb, std::vector<std::string> extra) {
    std::vector<std::string> args = {"export", scene.string(), "--out", vdb.string()};
    args.insert(args.end(), extra.begin(), extra.end());
    Exported e{sandbox(args), nullptr, nullptr};
    EXPECT_EQ(e.process.exitCode, 0) << explain(e.process);
    if (e.process.exitCode != 0) return e;
    EXPECT_EQ(e.process.out.find('\n'), e.process.out.size() - 1) << "one line of what it wrote: " << e.process.out;
    EXPECT_NE(e.process.out.find(vdb.string()), std::string::npos) << e.process.out;
    EXPECT_NE(e.process.out.find("active"), std::string::npos) << e.process.out;
    openvdb::initialize();
    openvdb::io::File file(vdb.string());
    file.open();
    e.grids = file.getGrids();
    file.close();
    for (const auto& g : *e.grids)
        if (g->getName() == "density") e.density = openvdb::gridPtrCast<openvdb::FloatGrid>(g);
    e.bytes = fs::file_size(vdb);
    return e;
}

struct GatheredMedium {
    media::ParticleSet particles;
    std::vector<media::Volume> volumes;
};

// The medium as every renderer gathers it at `time`.
GatheredMedium gather(const fs::path& scene, double time) {
    sandbox::Session session(sandbox::SessionOptions{scene, time, {}});
    GatheredMedium m;
    media::ecs::gatherParticles(session.app().world(), m.particles);
    media::ecs::gatherVolumes(session.app().world(), m.volumes);
    return m;
}

TEST(SandboxExport, ParticlesAndABoxRoundTripWithinTheStatedError) {
    const fs::path scene = kData / "volume_scenes/mixed.gltf";
    TempFolder out;
    const Exported e = exportScene(scene, out / "mixed.vdb", {"--time", "0"});
    ASSERT_TRUE(e.density);
    const GatheredMedium m = gather(scene, 0.0);
    ASSERT_FALSE(m.particles.empty());
    ASSERT_EQ(m.volumes.size(), 1u);
    const double h = e.density->voxelSize().x();

    std::mt19937 rng(3);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    double worstShare = 0.0, worstRelative = 0.0;
    for (int i = 0; i < 40; ++i) {
        // Through the cloud (centred near (0.5, 2, 0)) and through the fog bank (y 0..1).
        const glm::dvec3 target = i % 2 ? glm::dvec3(0.5 + 1.2 * unit(rng), 2.0 + 0.6 * unit(rng), 0.9 * unit(rng))
                                        : glm::dvec3(2.5 * unit(rng), 0.5 + 0.4 * unit(rng), 1.7 * unit(rng));
        const glm::dvec3 dir = glm::normalize(glm::dvec3(unit(rng), 0.5 * unit(rng), unit(rng)));
        const glm::dvec3 origin = target - 10.0 * dir;
        const double exact = media::test::closedFormOpticalDepth(m.particles, m.volumes, origin, dir, 0.0, 20.0);
        const double read = media::test::gridOpticalDepth(*e.density, origin, dir, 0.0, 20.0);
        const double bound = media::test::statedOpticalDepthError(m.particles, m.volumes, h, origin, dir);
        EXPECT_LE(std::abs(read - exact), bound + 1e-6) << "ray " << i << ": exact " << exact << ", read " << read;
        if (bound > 0.0) worstShare = std::max(worstShare, std::abs(read - exact) / bound);
        if (exact > 0.1) worstRelative = std::max(worstRelative, std::abs(read - exact) / exact);
    }
    std::printf("[ measured] mixed.gltf, voxel %.4g m, %.3g MB: worst relative error %.4f (tau > 0.1), worst share of the stated error %.3f\n", h,
                static_cast<double>(e.bytes) / 1e6, worstRelative, worstShare);
}

// ∫ σ ρ dV of one particle over its ball: σ R³ · 4π ∫₀¹ u² e^(−4.5u²) du.
double particleMass(double sigma, double radius) {
    const double a = media::kKernelFalloff;
    const double shell = std::sqrt(media::kPi) * std::erf(std::sqrt(a)) / (4.0 * a * std::sqrt(a)) - std::exp(-a) / (2.0 * a);
    return sigma * radius * radius * radius * 4.0 * media::kPi * shell;
}

TEST(SandboxExport, ContentSmokeExportsTheMassOfItsParticles) {
    const fs::path scene = kContent / "scenes/smoke.gltf";
    TempFolder out;
    const Exported e = exportScene(scene, out / "smoke.vdb", {"--time", "8"});
    ASSERT_TRUE(e.density);
    const GatheredMedium m = gather(scene, 8.0);
    ASSERT_GT(m.particles.size(), 100u);
    double expected = 0.0;
    for (std::size_t i = 0; i < m.particles.size(); ++i) expected += particleMass(m.particles.sigma[i], m.particles.radius[i]);
    const double h = e.density->voxelSize().x();
    double mass = 0.0;
    for (auto it = e.density->cbeginValueOn(); it; ++it) mass += static_cast<double>(*it) * static_cast<double>(it.getVoxelCount());
    mass *= h * h * h;
    EXPECT_NEAR(mass / expected, 1.0, 1e-3);
    std::printf("[ measured] smoke.gltf at t = 8 s: %zu particles, voxel %.4g m, %llu active voxels, %.3g MB; mass %.6g m^2 vs %.6g (%+.3f%%)\n",
                m.particles.size(), h, static_cast<unsigned long long>(e.density->activeVoxelCount()), static_cast<double>(e.bytes) / 1e6, mass,
                expected, 100.0 * (mass / expected - 1.0));
    std::printf("[ output  ] %s", e.process.out.c_str());
}

}  // namespace
}  // namespace nimbus::test
