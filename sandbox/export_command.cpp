// sandbox export SCENE --out F.vdb [--time T] [--voxel V]
// Writes the participating medium as the renderers see it at time T (the particles of static
// clouds, generators and emitters simulated to T, and the volumes) as OpenVDB grids in world
// metres (plugins/participating_media/vdb, docs/export.md), for a path tracer or a DCC tool.
// Every bad argument is refused in one line before the scene is loaded; so is a voxel that would
// make the grid absurdly large, and a scene with no medium at T.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>

#include "cli_options.h"
#include "commands.h"
#include "nimbus/base/error.h"
#include "nimbus/base/log.h"
#include "nimbus/media/ecs/media_plugin.h"
#include "nimbus/media/vdb/grid_plan.h"
#include "nimbus/media/vdb/medium_grids.h"
#include "session.h"

namespace nimbus::sandbox {
namespace {

namespace fs = std::filesystem;

struct ExportOptions {
    CLI::App* command = nullptr;  // for the arguments CLI11 did not take
    std::string scene;
    std::string out;
    std::string time = "0";
    std::string voxel;  // empty: chosen from the medium
};

bool endsWithVdb(const std::string& path) {
    std::string ext = fs::path(path).extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext == ".vdb" && fs::path(path).stem() != "";
}

// Everything the command line says, checked before the (possibly long) load and simulation.
void checkArguments(const ExportOptions& o, double& time, double& voxel) {
    if (const std::vector<std::string> extra = o.command->remaining(); !extra.empty())
        throwInputError("export", "", "", "unexpected argument " + extra.front() + " (sandbox export SCENE --out F.vdb [--time T] [--voxel V])");
    if (o.scene.empty()) throwInputError("export", "", "", "no scene given (sandbox export SCENE --out F.vdb [--time T] [--voxel V])");
    if (o.out.empty()) throwInputError("--out", "", "", "missing: the .vdb file to write (sandbox export SCENE --out F.vdb)");
    if (!endsWithVdb(o.out)) throwInputError("--out", o.out, "", "must name a .vdb file");
    const fs::path folder = fs::path(o.out).parent_path().empty() ? fs::path(".") : fs::path(o.out).parent_path();
    if (!fs::is_directory(folder)) throwInputError("--out", o.out, "", "its folder " + folder.string() + " does not exist");
    time = parseTime(o.time);
    voxel = o.voxel.empty() ? 0.0 : parsePositive(o.voxel, "--voxel", 1e6, "metres");
}

std::string formatted(const char* format, double a, double b = 0.0, double c = 0.0) {
    char buffer[512];
    std::snprintf(buffer, sizeof buffer, format, a, b, c);
    return buffer;
}

// "grids density, albedo; metadata emission (0, 0, 0), g 0.3": which attributes became grids, and
// the values of those that are metadata (for a user to type into a DCC tool's shader).
std::string layout(const media::vdb::MediumGrids& g) {
    const openvdb::FloatGrid& d = *g.density;
    std::string grids = "density", meta;
    auto colour = [&](const char* name) {
        const openvdb::Vec3s c = d.metaValue<openvdb::Vec3s>(name);
        return formatted(" (%.4g, %.4g, %.4g)", c.x(), c.y(), c.z());
    };
    auto place = [&](const char* name, bool isGrid, const std::string& value) {
        std::string& list = isGrid ? grids : meta;
        list += (list.empty() ? "" : ", ") + std::string(name) + (isGrid ? "" : value);
    };
    place("albedo", g.albedo != nullptr, g.albedo ? "" : colour("albedo"));
    place("emission", g.emission != nullptr, g.emission ? "" : colour("emission"));
    place("g", g.g != nullptr, g.g ? "" : formatted(" %.4g", d.metaValue<float>("g")));
    return "grids " + grids + (meta.empty() ? "" : "; metadata " + meta);
}

int run(const ExportOptions& o) {
    double time = 0.0, voxel = 0.0;
    checkArguments(o, time, voxel);
    const auto start = std::chrono::steady_clock::now();
    // The same Session every renderer starts from: the same simulation steps, poses and particles.
    Session session(SessionOptions{o.scene, time, {}});
    media::ParticleSet particles;
    std::vector<media::Volume> volumes;
    media::ecs::gatherParticles(session.app().world(), particles);
    media::ecs::gatherVolumes(session.app().world(), volumes);
    if (particles.empty() && volumes.empty())
        throwInputError(o.scene, "", "", "no medium at --time " + o.time + " (no particle alive and no volume): nothing to export");

    const media::vdb::GridPlan plan = media::vdb::planGrid(particles, volumes, voxel);
    if (!plan.fits)
        throwInputError("--voxel", o.voxel, "",
                        formatted("too small for this medium: about %.3g voxels, more than the %.3g an export holds; the smallest voxel that fits is %.3g m",
                                  plan.estimatedVoxels, media::vdb::kMaxVoxels, plan.smallestVoxel));
    log::info(formatted("export: voxel %.4g m, about %.3g active voxels of %.3g in the medium's box", plan.voxel, plan.estimatedVoxels, plan.boxVoxels));

    const media::vdb::MediumGrids grids = media::vdb::buildMediumGrids(particles, volumes, plan, /*progress=*/true);
    media::vdb::writeVdb(o.out, grids, {o.scene, time});

    const openvdb::CoordBBox box = grids.density->evalActiveVoxelBoundingBox();
    const openvdb::Coord dim = box.dim();
    const double h = plan.voxel;
    auto corner = [&](const openvdb::Coord& c, double side) {
        return formatted("(%.4g, %.4g, %.4g)", (c.x() + side) * h, (c.y() + side) * h, (c.z() + side) * h);
    };
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("export: %zu particles, %zu volume%s at t = %g s: voxel %.4g m%s, %dx%dx%d voxels, %llu active, bounds %s..%s m; %s; %.2f s -> %s (%.3g MB)\n",
                particles.size(), volumes.size(), volumes.size() == 1 ? "" : "s", time, h,
                plan.coarsened ? " (automatic, coarsened to fit)" : plan.automatic ? " (automatic)" : "", dim.x(), dim.y(), dim.z(),
                static_cast<unsigned long long>(grids.density->activeVoxelCount()), corner(box.min(), -0.5).c_str(),
                corner(box.max(), 0.5).c_str(), layout(grids).c_str(), seconds, o.out.c_str(),
                static_cast<double>(fs::file_size(o.out)) / 1e6);
    return 0;
}

}  // namespace

CommandRunner addExportCommand(CLI::App& app) {
    auto options = std::make_shared<ExportOptions>();
    auto* cmd = app.add_subcommand("export", "write the medium at a time as OpenVDB grids (density, albedo, emission) in world metres");
    // Checked by the command itself rather than by CLI11, so that every refusal is one line.
    cmd->allow_extras();
    options->command = cmd;
    cmd->add_option("scene", options->scene, "glTF scene (.gltf or .glb)");
    cmd->add_option("--out", options->out, "the .vdb file to write");
    addTimeOption(cmd, options->time, "scene time in seconds (animation, emitters)");
    cmd->add_option("--voxel", options->voxel, "voxel side in metres (default: from the medium, docs/export.md)");
    return [options] { return run(*options); };
}

}  // namespace nimbus::sandbox
