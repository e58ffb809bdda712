#include "bench_sweep.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <set>

#include <epoxy/gl.h>

#include "nimbus/base/settings.h"
#include "nimbus/media/ecs/media_plugin.h"
#include "nimbus/gpu/pass_timer.h"
#include "nimbus/render/render_plugin.h"

namespace nimbus::sandbox {
namespace {

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

}  // namespace

std::vector<BenchConfig> standardSweep(const media::ParticleSet& particles, const std::vector<glm::dvec3>& lamps, bool multiple) {
    std::vector<BenchConfig> sweep;
    auto add = [&](std::string name, std::vector<std::pair<std::string, std::string>> settings) {
        if (std::none_of(sweep.begin(), sweep.end(), [&](const BenchConfig& c) { return c.name == name; }))
            sweep.push_back({std::move(name), std::move(settings)});
    };
    // The tiers, then the budget's quality ladder (media_plugin.h), so its order can be checked
    // against the errors, then every mode's own rows. Rows without a quality are the exact tier's.
    add("fast", {{"quality", "fast"}});
    add("balanced", {{"quality", "balanced"}});
    for (const auto& rung : media::ecs::kQualityLadder)
        if (rung.tier != QualityTier::Exact) add(rung.name, rung.assignments());  // exact: the default mode's row
    add("fast slices=8", {{"quality", "fast"}, {"slices", "8"}});
    if (multiple) {  // the multiple model's own: its diffusion grid's voxels and relaxation sweeps
        for (const char* voxels : {"16", "64"}) add(std::string("fast scattering_voxels=") + voxels, {{"quality", "fast"}, {"scattering_voxels", voxels}});
        add("fast scattering_sweeps=8", {{"quality", "fast"}, {"scattering_sweeps", "8"}});
        add("balanced scattering_voxels=64", {{"quality", "balanced"}, {"scattering_voxels", "64"}});
    }
    // A named table: a range-for over a temporary's entries() would read a destroyed table.
    const media::TechniqueTable techniques = media::builtInTechniques();
    for (const media::TechniqueEntry& entry : techniques.entries())
        if (entry.benchRows)
            for (media::BenchRow& row : entry.benchRows(particles, lamps)) add(std::move(row.name), std::move(row.settings));
    return sweep;
}

namespace {

// Every key some configuration sets; each is cleared before the next configuration.
std::set<std::string> sweptKeys(const std::vector<BenchConfig>& configs) {
    std::set<std::string> keys;
    for (const BenchConfig& c : configs)
        for (const auto& [key, value] : c.settings) keys.insert(key);
    return keys;
}

}  // namespace

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
    const std::set<std::string> swept = sweptKeys(configs);
    for (std::size_t c = 0; c < configs.size(); ++c) {
        const BenchConfig& config = configs[c];
        for (const std::string& key : swept) settings.unset(key);
        for (const auto& [key, value] : config.settings) settings.set(key, value, "bench");
        BenchResult r;
        r.config = config;
        for (int i = 0; i < timing.warmup; ++i) app.redraw();

        std::vector<double> frames;
        for (int i = 0; i < timing.frames; ++i) {
            glFinish();
            const auto start = std::chrono::steady_clock::now();
            app.redraw();
            glFinish();
            frames.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
        }
        r.frameMs = gpu::median(frames);
        r.floorMs = splatFloor(app, width, height, timing.frames);  // right after the timed frames

        gpu::GlPassTimer timer;
        request.timer = &timer;
        for (int i = 0; i < timing.frames; ++i) app.redraw();
        request.timer = nullptr;
        for (const auto& [pass, samples] : timer.samples()) {
            r.passMs[pass] = gpu::median(samples);
            if (isMediaPass(pass)) r.mediaMs += r.passMs[pass];
        }

        const assets::RgbImage image = app.resource<render::RendererState>().renderer->readOutput();
        r.error = media::reference::compareImages(image, reference);
        if (const auto* state = app.world().tryResource<media::ecs::MediaRendererState>(); state && state->renderer) {
            r.slices = state->renderer->stats().slices;
            r.technique = state->renderer->stats().technique;
        }
        results.push_back(std::move(r));
        if (progress) progress(c + 1);
    }
    for (const std::string& key : swept) settings.unset(key);
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
