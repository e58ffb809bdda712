// sandbox render SCENE [--out F] [--size WxH] [--mode M] [--quality Q] [--budget-ms B] [--time T] [--camera NAME|INDEX] [--set K=V]...
//                      [--stats F.json] [--frames N] [--orbit DEG] [--animate] [--exposure E] [--tonemap none|filmic]
// Renders the scene headless (EGL) with the real-time renderer. With --stats it measures: the
// median frame time over N (≥ 20) GPU-synchronised frames after warm-up, and per-pass medians over
// another N frames timed pass by pass (synchronising each pass inflates the total, so the two are
// measured separately). With --orbit the camera turns between frames, so what a still camera
// reads again (blocks' impostor_reuse) is timed as a moving one sees it; with --animate the scene's
// simulation steps before each frame, so what a moving medium costs (the multiple model's grid
// solved again) is timed as a game pays it.
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <numeric>
#include <utility>
#include <variant>

#include <epoxy/gl.h>
#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include "commands.h"
#include "nimbus/assets/image_io.h"
#include "nimbus/base/error.h"
#include "nimbus/base/settings.h"
#include "nimbus/gpu/context.h"
#include "nimbus/media/ecs/media_plugin.h"
#include "nimbus/gpu/pass_timer.h"
#include "nimbus/render/render_plugin.h"
#include "cli_options.h"
#include "frame_budget_walk.h"
#include "session.h"

namespace nimbus::sandbox {
namespace {

struct RenderOptions {
    std::string scene;
    std::vector<std::string> out;
    std::string size = "1280x720";
    std::string mode;
    std::string quality;
    std::string time = "0";
    std::string camera;
    std::vector<std::string> settings;
    std::string stats;
    std::string frames = "20";
    std::string orbit = "0";
    bool animate = false;
    std::string exposure = "1";
    std::string tonemap = "none";
    bool floor = false;
    std::string budget;  // --budget-ms, as typed
    std::string scattering;  // empty: the scene's model
};

// What run() reads from the options' text, every value checked before any work starts.
struct RenderValues {
    int width = 0, height = 0;
    double time = 0.0;
    int frames = 20;
    double orbit = 0.0;  // degrees per frame
    float exposure = 1.0f;
    double budgetMs = 0.0;  // 0: no --budget-ms
};

RenderValues readValues(const RenderOptions& o) {
    RenderValues v;
    parseSize(o.size, v.width, v.height);
    v.time = parseTime(o.time);
    v.frames = parseCount(o.frames, "--frames", 20, 10000);
    if (o.orbit != "0") v.orbit = parsePositive(o.orbit, "--orbit", 90.0, "degrees per frame");
    v.exposure = static_cast<float>(parsePositive(o.exposure, "--exposure", 1e30));
    if (!o.budget.empty()) v.budgetMs = parsePositive(o.budget, "--budget-ms", 1e6, "milliseconds per frame");
    return v;
}

assets::ToneCurve parseToneCurve(const std::string& text) {
    if (text == "none") return assets::ToneCurve::None;
    if (text == "filmic") return assets::ToneCurve::Filmic;
    throwInputError("--tonemap", text, "", "unknown tone curve (known: none, filmic)");
}

// --orbit: before each frame, the camera turned `degrees` further about the vertical axis through
// the medium's centre (the world origin without a medium).
class Orbit {
public:
    Orbit(ecs::App& app, double degrees) : app_(app), degrees_(degrees), start_(app.resource<render::RendererState>().lastInput.camera) {
        const auto* media = app.world().tryResource<media::ecs::MediaRendererState>();
        if (media != nullptr && media->renderer) pivot_ = media->renderer->bounds().center();
    }
    void next() {
        if (degrees_ <= 0.0) return;
        assets::ResolvedCamera camera = start_;
        const glm::dmat4 turn = glm::translate(glm::dmat4(1.0), pivot_) *
                                glm::rotate(glm::dmat4(1.0), glm::radians(degrees_ * ++step_), glm::dvec3(0.0, 1.0, 0.0)) *
                                glm::translate(glm::dmat4(1.0), -pivot_);
        camera.world = turn * start_.world;
        app_.resource<render::RenderRequest>().cameraOverride = camera;
    }

private:
    ecs::App& app_;
    double degrees_;
    assets::ResolvedCamera start_;
    glm::dvec3 pivot_{0.0};
    int step_ = 0;
};

// One frame of the timed loops: the scene's simulation stepped first with --animate (app.update()
// runs every phase), else the same state drawn again.
void nextFrame(ecs::App& app, Orbit& orbit, bool animate) {
    orbit.next();
    if (animate)
        app.update();
    else
        app.redraw();
}

// The multiple model's grid solve this frame: its CPU ms (0: kept, or no media) and whether it
// started from the last frame's answer.
std::pair<double, bool> scatteringSolve(ecs::App& app) {
    const auto* media = app.world().tryResource<media::ecs::MediaRendererState>();
    if (media == nullptr || !media->renderer) return {0.0, false};
    return {media->renderer->stats().scatteringSolveMs, media->renderer->stats().scatteringWarm};
}

// The median frame over `frames` GPU-synchronised frames after a warm-up, then per-pass medians over
// as many more, each pass synchronised (which inflates the total, so the two are measured apart).
void measureFrames(ecs::App& app, int frames, double orbitDegrees, bool animate, nlohmann::json& stats) {
    using Clock = std::chrono::steady_clock;
    Orbit orbit(app, orbitDegrees);
    for (int i = 0; i < 3; ++i) nextFrame(app, orbit, animate);  // warm-up: shader compiles, pool fills
    std::vector<double> ms, solveMs;
    int warmSolves = 0;
    for (int i = 0; i < frames; ++i) {
        glFinish();
        const auto start = Clock::now();
        nextFrame(app, orbit, animate);
        glFinish();
        ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
        const auto [solve, warm] = scatteringSolve(app);
        solveMs.push_back(solve);
        warmSolves += warm ? 1 : 0;
    }
    auto& request = app.resource<render::RenderRequest>();
    gpu::GlPassTimer timer;
    request.timer = &timer;
    for (int i = 0; i < frames; ++i) nextFrame(app, orbit, animate);
    request.timer = nullptr;
    nlohmann::json passes = nlohmann::json::object();
    for (const auto& [name, samples] : timer.samples()) passes[name] = gpu::median(samples);
    stats["frame_ms"] = gpu::median(ms);
    stats["frame_ms_min"] = *std::min_element(ms.begin(), ms.end());
    // What frames cost on average: the median hides a cache's occasional refresh (--orbit).
    stats["frame_ms_mean"] = std::accumulate(ms.begin(), ms.end(), 0.0) / static_cast<double>(ms.size());
    stats["frames"] = frames;
    if (orbitDegrees > 0.0) stats["orbit_deg_per_frame"] = orbitDegrees;
    stats["animate"] = animate;
    // On the CPU, inside frame_ms: 0 for a still medium, whose grid the first frame solved.
    stats["media_scattering_solve_ms"] = gpu::median(solveMs);
    stats["media_scattering_warm_frames"] = warmSolves;  // of them, solved from the frame before's (scattering_warm_sweeps)
    stats["passes_ms"] = passes;
}

// What the media renderer did this frame: the shared figures and its technique's own.
void addMediaStats(ecs::App& app, nlohmann::json& stats) {
    const auto* media = app.world().tryResource<media::ecs::MediaRendererState>();
    if (media == nullptr || !media->renderer) return;
    const media::MediaFrameStats& s = media->renderer->stats();
    stats["media_mode"] = s.mode;
    if (const auto quality = app.resource<Settings>().text("quality")) stats["quality"] = *quality;
    stats["media_particles"] = s.particles;
    stats["media_slices"] = s.slices;
    stats["media_slice_views"] = s.sliceViews;
    stats["media_slice_crops"] = s.slicesCropped;
    stats["media_multiple_scattering"] = s.multipleScattering;
    stats["media_rescatter"] = s.rescatter;
    // What the "auto" settings chose this frame.
    stats["media_slice_resolution"] = s.sliceResolution;
    stats["media_scale_used"] = s.mediaScale;
    for (const media::TechniqueStat& t : s.technique) std::visit([&](auto v) { stats["media_" + t.key] = v; }, t.value);
}

void writeStats(const RenderOptions& o, Session& session, const gpu::Context& context, std::uint64_t glErrors, nlohmann::json& stats) {
    ecs::App& app = session.app();
    const auto& state = app.resource<render::RendererState>();
    stats["scene"] = o.scene;
    stats["time"] = session.time();
    stats["camera"] = state.lastInput.camera.name;
    stats["gl_renderer"] = context.renderer();
    stats["gl_version"] = context.version();
    stats["gl_errors"] = glErrors;
    stats["active_passes"] = state.renderer->lastActivePasses();
    addMediaStats(app, stats);
    std::ofstream file(o.stats);
    if (!file) throwInputError(o.stats, "", "", "cannot write the stats file");
    file << stats.dump(2) << "\n";
}

// The session for the options, with rendering on at width×height; bad input is refused before any GL work.
std::unique_ptr<Session> openSession(const RenderOptions& o, const RenderValues& v) {
    SessionOptions options{o.scene, v.time, o.settings};
    if (!o.scattering.empty()) options.scattering = parseScattering(o.scattering);
    if (!o.mode.empty()) options.options.emplace_back("mode=" + o.mode, "--mode");
    if (!o.quality.empty()) options.options.emplace_back("quality=" + o.quality, "--quality");
    options.defaultQuality = kRenderDefaultQuality;
    options.refuseIdle = v.budgetMs == 0.0;  // the walk checks each rung itself
    auto session = std::make_unique<Session>(options);
    auto& request = session->app().resource<render::RenderRequest>();
    request.enabled = true;
    request.settings.width = v.width;
    request.settings.height = v.height;
    request.camera = o.camera;
    return session;
}

int run(const RenderOptions& o) {
    const RenderValues v = readValues(o);
    const int width = v.width, height = v.height;
    const double budgetMs = v.budgetMs;
    const assets::ToneCurve curve = parseToneCurve(o.tonemap);
    std::unique_ptr<gpu::Context> context;  // declared first: it must outlive the GL objects the session makes
    std::unique_ptr<Session> session = openSession(o, v);
    context = gpu::Context::create();
    ecs::App& app = session->app();

    nlohmann::json stats;
    if (budgetMs > 0.0) {
        const BudgetChoice choice = settleOnBudget(app, budgetMs);
        std::printf("budget %.1f ms: chose %s (median %.1f ms while walking the quality ladder, %d frames)\n", budgetMs,
                    choice.rung.c_str(), choice.medianMs, choice.framesRendered);
        stats["budget_ms"] = budgetMs;
        stats["chosen"] = choice.rung;
    }
    app.redraw();
    if (!o.stats.empty()) measureFrames(app, v.frames, v.orbit, o.animate, stats);
    auto& state = app.resource<render::RendererState>();
    const assets::RgbImage image = state.renderer->readOutput();
    if (o.floor) {  // right after the timed frames, in the same process: the scene's fixed yardstick
        const auto* media = app.world().tryResource<media::ecs::MediaRendererState>();
        const render::View view = render::makeView(state.lastInput.camera, width, height);
        stats["splat_floor_ms"] = media && media->renderer ? media->renderer->measureSplatFloor(view, v.frames) : 0.0;
    }
    const gpu::GlErrorReport errors = context->takeGlErrors();
    for (const auto& file : o.out) assets::writeImage(file, image, {v.exposure, curve});
    stats["width"] = width;
    stats["height"] = height;
    if (!o.stats.empty()) writeStats(o, *session, *context, errors.count, stats);
    if (errors.count > 0) {
        std::fprintf(stderr, "sandbox render: %llu GL error(s), first: %s\n", static_cast<unsigned long long>(errors.count),
                     errors.first.c_str());
        return 1;
    }
    std::string outputs;
    for (const auto& file : o.out) outputs += (outputs.empty() ? " -> " : ", ") + file;
    std::printf("rendered %s at %dx%d (camera %s, t=%.3f s)%s\n", o.scene.c_str(), width, height,
                state.lastInput.camera.name.c_str(), session->time(), outputs.c_str());
    if (stats.contains("frame_ms"))
        std::printf("frame_ms %.3f (median of %d, %s)\n", stats["frame_ms"].get<double>(), v.frames, context->renderer().c_str());
    return 0;
}

}  // namespace

CommandRunner addRenderCommand(CLI::App& app) {
    auto options = std::make_shared<RenderOptions>();
    auto* cmd = app.add_subcommand("render", "render a scene with the real-time renderer (headless)");
    cmd->add_option("scene", options->scene, "glTF scene (.gltf or .glb)")->required();
    cmd->add_option("--out", options->out, "output image: .exr (linear radiance) or .png (sRGB); repeatable");
    cmd->add_option("--size", options->size, "image size WxH")->capture_default_str();
    cmd->add_option("--mode", options->mode, settingOptionHelp("mode", "how the medium is drawn", "the scene's, else particles"));
    cmd->add_option("--quality", options->quality, settingOptionHelp("quality", "the quality tier", "the scene's, else balanced"));
    cmd->add_option("--scattering", options->scattering, "the optical model instead of the scene's: single or multiple");
    cmd->add_option("--budget-ms", options->budget,
                    "frame budget: walk the quality ladder and keep the lowest-error setting whose frames fit");
    addTimeOption(cmd, options->time);
    cmd->add_option("--camera", options->camera, "camera: a camera or node name, or an index into the file's cameras; default: the scene's first");
    cmd->add_option("--set", options->settings, "KEY=VALUE setting (repeatable; `sandbox settings` lists them)");
    cmd->add_option("--stats", options->stats, "write frame timings and renderer info as JSON");
    cmd->add_option("--frames", options->frames, "timed frames for --stats, 20..10000")->capture_default_str();
    cmd->add_option("--orbit", options->orbit,
                    "with --stats: degrees the camera turns before each frame about the vertical axis through the medium's centre "
                    "(what a still camera reads again is timed as a moving one sees it); the image written is the last frame's")
        ->needs(cmd->get_option("--stats"));
    cmd->add_flag("--animate", options->animate,
                  "with --stats: step the scene's simulation (1/60 s) before each frame, so what a moving medium costs is timed "
                  "(the multiple model's grid solved again: media_scattering_solve_ms); the image written is the last frame's, "
                  "at the time the stats give")
        ->needs(cmd->get_option("--stats"));
    cmd->add_option("--exposure", options->exposure, "PNG exposure multiplier, a finite number > 0")->capture_default_str();
    cmd->add_option("--tonemap", options->tonemap, "PNG tone curve after the exposure: none (clip at 1) or filmic (ACES fit); EXR stays linear")
        ->capture_default_str();
    cmd->add_flag("--floor", options->floor, "with --stats: also measure splat_floor_ms, every particle's billboard blended once")
        ->needs(cmd->get_option("--stats"));
    return [options] { return run(*options); };
}

}  // namespace nimbus::sandbox
