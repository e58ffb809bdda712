// sandbox bench SCENE [--out DIR] [--size WxH] [--time T] [--frames N] [--scaling] [--only NAME]...
//                     [--scattering single|multiple] [--spp N]
// docs/design.md §6: renders the reference once, then sweeps the settings that trade speed for error
// (modes, slices, blocks, impostor resolution, instancing, media scale), measuring each one's
// frame time (median of N GPU-synchronised frames, per pass), its error against the reference, and
// the splat floor (every particle's billboard blended once). --scaling adds a sweep of particle
// count (1k → 1M, a synthetic cloud in the scene's media bounds) and resolution, timed only.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <map>
#include <random>
#include <variant>

#include <epoxy/gl.h>

#include "bench_report.h"
#include "bench_sweep.h"
#include "cli_options.h"
#include "commands.h"
#include "nimbus/base/error.h"
#include "nimbus/base/progress.h"
#include "nimbus/base/settings.h"
#include "nimbus/gpu/context.h"
#include "nimbus/media/block_partition.h"
#include "nimbus/media/ecs/media_plugin.h"
#include "nimbus/media/media_renderer.h"
#include "nimbus/media/reference/image_metrics.h"
#include "nimbus/gpu/pass_timer.h"
#include "nimbus/render/render_plugin.h"
#include "nimbus/scene/scene_plugin.h"
#include "session.h"

namespace nimbus::sandbox {
namespace {

struct BenchOptions {
    std::string scene;
    std::string out = "out/bench";
    std::string size = "640x360";
    std::string time = "0";
    std::string frames = "20";
    bool scaling = false;
    std::vector<std::string> only;
    std::string tolerance = "0.0001";
    std::string scattering;  // empty: the scene's model
    int spp = 64;            // the multiple model's reference: paths per pixel
};

// The reference's own noise in the units of rel-RMSE: an image one standard error off in every
// pixel, against the reference.
double noiseRelRmse(const assets::RgbImage& standardError, const assets::RgbImage& image) {
    assets::RgbImage offset = image;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) offset.set(x, y, image.at(x, y) + standardError.at(x, y));
    return media::reference::compareImages(offset, image).relRmse;
}

std::string isoDate() {
    const std::time_t now = std::time(nullptr);
    char buffer[32];
    std::strftime(buffer, sizeof buffer, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
    return buffer;
}

// A cloud of `count` particles filling the ellipsoid inscribed in `bounds`, overlapping about twice,
// with a column optical depth of about 2 whatever the count (so only the cost changes).
media::ParticleSet syntheticCloud(std::size_t count, const assets::Aabb& bounds, std::uint64_t seed) {
    const glm::dvec3 centre = bounds.center(), half = 0.5 * bounds.extent();
    const double volume = 4.0 / 3.0 * 3.14159265358979 * half.x * half.y * half.z;
    const double radius = std::cbrt(2.0 * volume / (static_cast<double>(count) * 4.0 / 3.0 * 3.14159265358979));
    const double column = 2.0 * std::max({half.x, half.y, half.z});
    const double perParticle = static_cast<double>(count) / volume * 3.14159265358979 * radius * radius * column;
    const auto sigma = static_cast<float>(2.0 / (perParticle * 0.6 * radius));
    media::Medium medium;
    medium.albedo = glm::vec3(0.9f);
    medium.g = 0.5f;
    std::mt19937_64 random(seed);
    auto uniform = [&] { return static_cast<double>(random() >> 11) * 0x1.0p-53 * 2.0 - 1.0; };
    media::ParticleSet set;
    set.reserve(count);
    while (set.size() < count) {
        const double z = uniform(), y = uniform(), x = uniform();  // in sequence: the same cloud from every compiler
        const glm::dvec3 p(x, y, z);
        if (glm::dot(p, p) > 1.0) continue;
        set.push(centre + p * half, static_cast<float>(radius), sigma, medium);
    }
    return set;
}

nlohmann::json runScaling(Session& session, const media::ParticleSet& sceneParticles, int frames) {
    ecs::App& app = session.app();
    auto& state = app.resource<render::RendererState>();
    assets::Aabb bounds = media::particleBounds(sceneParticles);
    if (bounds.empty()) bounds = assets::meshBounds(session.scene(), scene::currentWorldTransforms(app.world()));
    const std::size_t counts[] = {1000, 10000, 100000, 1000000};
    const glm::ivec2 sizes[] = {{320, 180}, {640, 360}, {1280, 720}};
    // The exact tier of every mode in the scaling sweep, and the default mode's fast tier.
    std::vector<std::pair<std::string, std::string>> tiers;
    // A named table: a range-for over a temporary's entries() would read a destroyed table.
    const media::TechniqueTable techniques = media::builtInTechniques();
    for (const media::TechniqueEntry& entry : techniques.entries())
        if (entry.scalingBench) tiers.emplace_back(entry.name, "mode=" + entry.name);
    tiers.emplace_back("fast", "quality=fast");
    constexpr double kBudgetMs = 8000.0;  // a setting whose 10× smaller case took a tenth of this is skipped
    nlohmann::json rows = nlohmann::json::array();
    ProgressBar progress("scaling", std::size(counts) * std::size(sizes) * std::size(tiers));
    std::map<std::pair<int, int>, double> lastMs;  // (tier, size index) → ms at the previous count
    for (const std::size_t count : counts) {
        const media::ParticleSet cloud = syntheticCloud(count, bounds, 7);
        for (std::size_t s = 0; s < std::size(sizes); ++s) {
            for (std::size_t t = 0; t < std::size(tiers); ++t) {
                progress.advance();
                nlohmann::json row{{"mode", tiers[t].first}, {"particles", count}, {"width", sizes[s].x}, {"height", sizes[s].y}};
                const auto key = std::make_pair(static_cast<int>(t), static_cast<int>(s));
                if (lastMs.count(key) && lastMs[key] * 10.0 > kBudgetMs) {
                    row["frame_ms"] = nullptr;
                    row["skipped"] = "the 10x smaller cloud already took " + std::to_string(lastMs[key]) + " ms";
                    rows.push_back(row);
                    continue;
                }
                Settings tierSettings = app.resource<Settings>();
                tierSettings.assign(tiers[t].second, "bench --scaling");
                render::RenderSettings settings;
                render::readRenderSettings(tierSettings, settings);
                settings.width = sizes[s].x;
                settings.height = sizes[s].y;
                media::MediaRenderer medium;  // the core through the host contract, without the ECS
                media::MediaRenderExtension extension(medium);
                medium.prepare(cloud, media::ecs::readMediaSettings(&tierSettings));
                render::FrameInput input = render::gatherFrameInput(app.world(), settings, "", medium.bounds());
                input.gpuScene = state.gpuScene.get();
                render::RenderExtension* extensions[] = {&extension};
                state.renderer->render(input, settings, extensions);  // warm-up
                std::vector<double> ms;
                for (int f = 0; f < frames; ++f) {
                    glFinish();
                    const auto start = std::chrono::steady_clock::now();
                    state.renderer->render(input, settings, extensions);
                    glFinish();
                    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
                }
                lastMs[key] = gpu::median(ms);
                row["frame_ms"] = lastMs[key];
                row["splat_floor_ms"] = medium.measureSplatFloor(render::makeView(input.camera, settings.width, settings.height), frames);
                row["frames"] = frames;
                for (const media::TechniqueStat& stat : medium.stats().technique)
                    std::visit([&](auto v) { row[stat.key] = v; }, stat.value);
                rows.push_back(row);
            }
        }
    }
    return rows;
}

int run(const BenchOptions& o) {
    int width = 0, height = 0;
    parseSize(o.size, width, height);
    const int frames = parseCount(o.frames, "--frames", 20, 10000);
    const double tolerance = parsePositive(o.tolerance, "--tolerance", 0.1);
    std::unique_ptr<gpu::Context> context;  // outlives the session's GL objects
    SessionOptions sessionOptions{.scene = o.scene, .time = parseTime(o.time)};
    if (!o.scattering.empty()) sessionOptions.scattering = parseScattering(o.scattering);
    auto session = std::make_unique<Session>(sessionOptions);
    context = gpu::Context::create();

    BenchRun run;
    run.scene = o.scene;
    run.time = session->time();
    run.width = width;
    run.height = height;
    run.glRenderer = context->renderer();
    run.date = isoDate();
    run.scattering = session->scene().environment.scattering == assets::Scattering::Single ? "single" : "multiple";

    const auto referenceStart = std::chrono::steady_clock::now();
    const auto reference = makeReferenceScene(*session, "", width, height);
    run.particles = reference->particles.size();
    // Every --only names a setting of the sweep, checked before the reference's minutes are spent.
    std::vector<BenchConfig> configs = standardSweep(reference->particles, media::lampPositions(render::punctualLights(reference->inputs.lights)),
                                                     run.scattering == "multiple");
    for (const std::string& name : o.only)
        if (std::none_of(configs.begin(), configs.end(), [&](const BenchConfig& c) { return c.name == name; }))
            throwInputError("--only", name, "", "matches no setting of the sweep");
    if (!o.only.empty())
        std::erase_if(configs, [&](const BenchConfig& c) { return std::find(o.only.begin(), o.only.end(), c.name) == o.only.end(); });
    media::reference::ReferenceSettings referenceSettings;
    referenceSettings.width = width;
    referenceSettings.height = height;
    referenceSettings.tolerance = tolerance;
    referenceSettings.spp = o.spp;
    media::reference::ReferenceStats referenceStats;
    assets::RgbImage standardError;
    const assets::RgbImage referenceImage =
        media::reference::renderReference(reference->inputs, referenceSettings, &referenceStats, &standardError);
    if (referenceStats.multiple) {
        run.referenceSpp = o.spp;
        run.referenceNoise = noiseRelRmse(standardError, referenceImage);
    }
    run.referenceSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - referenceStart).count();

    {
        ProgressBar progress("bench " + std::to_string(configs.size()) + " settings", configs.size());
        run.results = runSweep(*session, configs, width, height, referenceImage, {frames, 3},
                               [&](std::size_t) { progress.advance(); });
    }
    if (o.scaling) run.scaling = runScaling(*session, reference->particles, 5);
    if (const auto errors = context->takeGlErrors(); errors.count > 0)
        throw SystemError("GL error during the benchmark: " + errors.first);

    const std::string plot = writeBenchFiles(run, o.out);
    std::printf("bench %s: %dx%d, %zu particles, %s scattering, reference %.1f s, %s\n", o.scene.c_str(), width, height,
                run.particles, run.scattering.c_str(), run.referenceSeconds, run.glRenderer.c_str());
    std::printf("%s", markdownTable(run).c_str());
    std::printf("wrote %s/bench.{json,csv,md}; %s\n", o.out.c_str(), plot.c_str());
    return 0;
}

}  // namespace

CommandRunner addBenchCommand(CLI::App& app) {
    auto options = std::make_shared<BenchOptions>();
    auto* cmd = app.add_subcommand("bench", "sweep settings: frame time against error, with the splat floor");
    cmd->add_option("scene", options->scene, "glTF scene (.gltf or .glb)")->required();
    cmd->add_option("--out", options->out, "output folder")->capture_default_str();
    cmd->add_option("--size", options->size, "image size WxH")->capture_default_str();
    addTimeOption(cmd, options->time);
    cmd->add_option("--frames", options->frames, "timed frames per setting, 20..10000")->capture_default_str();
    cmd->add_flag("--scaling", options->scaling, "also sweep particle count (1k..1M) and resolution");
    cmd->add_option("--only", options->only, "measure only these settings of the sweep (repeatable)");
    cmd->add_option("--tolerance", options->tolerance, "reference quadrature tolerance, in (0, 0.1]")->capture_default_str();
    cmd->add_option("--scattering", options->scattering,
                    "the optical model instead of the scene's: single or multiple (multiple's reference is Monte Carlo: "
                    "its noise enters every row's error)");
    cmd->add_option("--spp", options->spp, "multiple scattering: the reference's paths per pixel")->capture_default_str()->check(CLI::Range(1, 1 << 20));
    return [options] { return run(*options); };
}

}  // namespace nimbus::sandbox
