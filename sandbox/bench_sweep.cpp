#include "bench_sweep.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <epoxy/gl.h>

#include "nimbus/base/settings.h"
#include "nimbus/media/block_partition.h"
#include "nimbus/media/ecs/media_plugin.h"
#include "nimbus/gpu/pass_timer.h"
#include "nimbus/render/render_plugin.h"

namespace nimbus::sandbox {
namespace {

// Every key a configuration may set; each is cleared before the next configuration.
const char* const kSweptKeys[] = {"quality", "mode", "lighting", "slices", "slice_resolution", "slice_deposit", "blocks",
                                  "impostor_scale", "instancing", "media_scale", "soft_particles", "layer_light",
                                  "block_shading", "pcf_radius", "shadow_map_size"};

bool isMediaPass(const std::string& name) {
    return name.rfind("light_slice", 0) == 0 || name.rfind("media_", 0) == 0 || name.rfind("block_", 0) == 0;
}

// The splat floor of the frame just rendered (media_renderer.h measureSplatFloor): 0 without media.
double splatFloor(ecs::App& app, int width, int height, int repeats) {
    const auto* media = app.world().tryResource<media::ecs::MediaRendererState>();
    if (media == nullptr || !media->renderer) return 0.0;
    const auto& state = app.resource<render::RendererState>();
    return media->renderer->measureSplatFloor(render::makeView(state.lastInput.camera, width, height), repeats);
}

void renderFrame(ecs::App& app) {
    app.runPhase(ecs::phases::kPrepare);
    app.runPhase(ecs::phases::kRender);
    app.runPhase(ecs::phases::kPresent);
}

}  // namespace

std::vector<BenchConfig> standardSweep(const media::ParticleSet& particles, const std::vector<glm::dvec3>& lamps) {
    const int autoBlocks = media::automaticBlockCount(particles, lamps);
    std::vector<BenchConfig> sweep;
    auto add = [&](std::string name, std::vector<std::pair<std::string, std::string>> settings) {
        sweep.push_back({std::move(name), std::move(settings)});
    };
    // The tiers (quality presets) and the yardstick a typical engine ships, then the exact tier's
    // settings one at a time. Rows without a quality are the exact tier's.
    add("fast", {{"quality", "fast"}});
    add("balanced", {{"quality", "balanced"}});
    add("billboards", {{"mode", "billboards"}});
    // The budget's quality ladder (media_plugin.h), so its order can be checked against the errors.
    for (const auto& rung : media::ecs::kQualityLadder) {
        if (std::string(rung.name) == "exact") continue;  // the `particles` row below
        if (std::none_of(sweep.begin(), sweep.end(), [&](const BenchConfig& c) { return c.name == rung.name; }))
            add(rung.name, {rung.settings.begin(), rung.settings.end()});
    }
    add("fast slices=8", {{"quality", "fast"}, {"slices", "8"}});
    add("particles", {{"mode", "particles"}});
    for (const char* slices : {"4", "8", "16", "32"}) add(std::string("particles slices=") + slices, {{"mode", "particles"}, {"slices", slices}});
    add("particles layer_light=off", {{"mode", "particles"}, {"layer_light", "off"}});
    add("particles media_scale=0.5", {{"mode", "particles"}, {"media_scale", "0.5"}});
    add("particles media_scale=0.25", {{"mode", "particles"}, {"media_scale", "0.25"}});
    add("blocks", {{"mode", "blocks"}});
    for (const int blocks : {std::max(1, autoBlocks / 4), std::max(1, autoBlocks / 2), autoBlocks * 2, autoBlocks * 4}) {
        if (blocks == autoBlocks || static_cast<std::size_t>(blocks) > particles.size()) continue;
        add("blocks blocks=" + std::to_string(blocks), {{"mode", "blocks"}, {"blocks", std::to_string(blocks)}});
    }
    add("blocks impostor_scale=0.25", {{"mode", "blocks"}, {"impostor_scale", "0.25"}});
    add("blocks impostor_scale=1", {{"mode", "blocks"}, {"impostor_scale", "1"}});
    add("blocks slices=8", {{"mode", "blocks"}, {"slices", "8"}});
    add("blocks instancing", {{"mode", "blocks"}, {"instancing", "on"}});
    add("blocks media_scale=0.5", {{"mode", "blocks"}, {"media_scale", "0.5"}});
    // Change only the blocks where a mesh is seen inside the medium (blocksShadedExactly): the same
    // frame as `blocks` (block_shading=seam) on a scene without one.
    add("blocks block_shading=smooth", {{"mode", "blocks"}, {"block_shading", "smooth"}});
    add("blocks block_shading=exact", {{"mode", "blocks"}, {"block_shading", "exact"}});
    return sweep;
}

std::vector<BenchResult> runSweep(Session& session, const std::vector<BenchConfig>& configs, int width, int height,
                                  const assets::RgbImage& reference, const BenchTiming& timing,
                                  const std::function<void(std::size_t)>& progress) {
    ecs::App& app = session.app();
    auto& settings = app.resource<Settings>();
    auto& request = app.resource<render::RenderRequest>();
    request.enabled = true;
    request.settings.width = width;
    request.settings.height = height;
    std::vector<BenchResult> results;
    for (std::size_t c = 0; c < configs.size(); ++c) {
        const BenchConfig& config = configs[c];
        for (const char* key : kSweptKeys) settings.unset(key);
        for (const auto& [key, value] : config.settings) settings.set(key, value, "bench");
        BenchResult r;
        r.config = config;
        for (int i = 0; i < timing.warmup; ++i) renderFrame(app);

        std::vector<double> frames;
        for (int i = 0; i < timing.frames; ++i) {
            glFinish();
            const auto start = std::chrono::steady_clock::now();
            renderFrame(app);
            glFinish();
            frames.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
        }
        r.frameMs = gpu::median(frames);
        r.floorMs = splatFloor(app, width, height, timing.frames);  // right after the timed frames

        gpu::GlPassTimer timer;
        request.timer = &timer;
        for (int i = 0; i < timing.frames; ++i) renderFrame(app);
        request.timer = nullptr;
        for (const auto& [pass, samples] : timer.samples()) {
            r.passMs[pass] = gpu::median(samples);
            if (isMediaPass(pass)) r.mediaMs += r.passMs[pass];
        }

        const assets::RgbImage image = app.resource<render::RendererState>().renderer->readOutput();
        r.error = media::reference::compareImages(image, reference);
        if (const auto* state = app.world().tryResource<media::ecs::MediaRendererState>(); state && state->renderer) {
            r.slices = state->renderer->stats().slices;
            r.blocks = state->renderer->stats().blocks;
        }
        results.push_back(std::move(r));
        if (progress) progress(c + 1);
    }
    for (const char* key : kSweptKeys) settings.unset(key);
    markPareto(results);
    return results;
}

void markPareto(std::vector<BenchResult>& results) {
    for (auto& a : results) {
        a.pareto = std::none_of(results.begin(), results.end(), [&](const BenchResult& b) {
            const bool noWorse = b.frameMs <= a.frameMs && b.error.relRmse <= a.error.relRmse;
            const bool better = b.frameMs < a.frameMs || b.error.relRmse < a.error.relRmse;
            return &a != &b && noWorse && better;
        });
    }
}

}  // namespace nimbus::sandbox
