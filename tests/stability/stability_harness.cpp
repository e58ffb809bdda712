#include "stability_harness.h"

#include <malloc.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <map>

#include <epoxy/gl.h>

#include "nimbus/base/settings.h"
#include "nimbus/media/ecs/media_plugin.h"
#include "nimbus/media/reference/reference_renderer.h"

namespace nimbus::stability {

namespace reference = media::reference;

std::filesystem::path sceneDirectory() { return std::filesystem::path(NIMBUS_TEST_DATA_DIR) / "stability_scenes"; }

std::size_t countNonfinite(const assets::RgbImage& image) {
    std::size_t count = 0;
    for (std::size_t p = 0; p < image.pixelCount(); ++p) {
        const float* v = &image.rgb[3 * p];
        if (!std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2])) ++count;
    }
    return count;
}

double relativeRmsChange(const assets::RgbImage& a, const assets::RgbImage& b) {
    double change = 0.0, energy = 0.0;
    for (std::size_t i = 0; i < b.rgb.size() && i < a.rgb.size(); ++i) {
        const double d = static_cast<double>(a.rgb[i]) - static_cast<double>(b.rgb[i]);
        change += d * d;
        energy += static_cast<double>(b.rgb[i]) * static_cast<double>(b.rgb[i]);
    }
    if (change == 0.0) return 0.0;
    return energy > 0.0 ? std::sqrt(change / energy) : std::numeric_limits<double>::infinity();
}

double sparsity(const assets::RgbImage& image) {
    double energy = 0.0, luminance = 0.0;
    for (std::size_t p = 0; p < image.pixelCount(); ++p) {
        const float* v = &image.rgb[3 * p];
        for (int c = 0; c < 3; ++c) energy += static_cast<double>(v[c]) * static_cast<double>(v[c]);
        luminance += reference::luminance(v[0], v[1], v[2]);
    }
    if (image.pixelCount() == 0 || !(luminance > 0.0)) return 0.0;
    const double n = static_cast<double>(image.pixelCount());
    return std::sqrt(energy / (3.0 * n)) / (luminance / n);
}

const char* tierName(Tier tier) {
    switch (tier) {
        case Tier::Particles: return "particles";
        case Tier::Blocks: return "blocks";
        case Tier::Balanced: return "balanced";
        case Tier::Fast: return "fast";
    }
    return "unknown";
}

double boundedError(const CaseRun& run, Tier tier) {
    const ModeRun& m = run.tier(tier);
    return run.referenceSparsity >= kSparseImageRatio ? m.rmsRelativeError : m.error.relRmse;
}

double boundedError(const CaseRun& run, MediaMode mode) {
    return boundedError(run, mode == MediaMode::Blocks ? Tier::Blocks : Tier::Particles);
}

assets::RgbImage renderReference(sandbox::Session& session, const std::string& camera, int width, int height,
                                 double tolerance) {
    const auto scene = sandbox::makeReferenceScene(session, camera, width, height);
    reference::ReferenceSettings settings;
    settings.scattering = assets::Scattering::Single;  // today's real-time model
    settings.width = width;
    settings.height = height;
    settings.tolerance = tolerance;
    settings.progress = false;
    return reference::renderReference(scene->inputs, settings);
}

assets::RgbImage renderTier(sandbox::Session& session, Tier tier, int width, int height, const std::string& camera) {
    auto& settings = session.app().resource<Settings>();
    settings.set("mode", tier == Tier::Blocks ? "blocks" : "particles", "stability test");
    settings.set("quality", tier == Tier::Balanced ? "balanced" : tier == Tier::Fast ? "fast" : "exact", "stability test");
    return session.renderRealtime(width, height, camera);
}

media::MediaFrameStats mediaStats(sandbox::Session& session) {
    const auto* state = session.app().world().tryResource<media::ecs::MediaRendererState>();
    return state != nullptr && state->renderer ? state->renderer->stats() : media::MediaFrameStats{};
}

ModeRun runTier(gpu::Context& context, sandbox::Session& session, const HardCase& c, Tier tier, const assets::RgbImage& referenceImage) {
    ModeRun run;
    run.tier = tier;
    run.mode = tier == Tier::Blocks ? MediaMode::Blocks : MediaMode::Particles;
    (void)context.takeGlErrors();
    auto& settings = session.app().resource<Settings>();
    settings.set("mode", tier == Tier::Blocks ? "blocks" : "particles", "stability test");  // before the mode's own settings
    for (const std::string& kv : c.blockSettings)
        if (const auto eq = kv.find('='); tier == Tier::Blocks) settings.set(kv.substr(0, eq), kv.substr(eq + 1), "stability test");
    run.image = renderTier(session, tier, c.width, c.height, c.camera);
    const assets::RgbImage second = renderTier(session, tier, c.width, c.height, c.camera);
    for (const std::string& kv : c.blockSettings) settings.unset(kv.substr(0, kv.find('=')));
    run.glErrors = context.takeGlErrors();
    run.stats = mediaStats(session);
    run.nonfinite = countNonfinite(run.image);
    run.repeatNonfinite = countNonfinite(second);
    run.error = reference::compareImages(run.image, referenceImage);
    run.rmsRelativeError = relativeRmsChange(run.image, referenceImage);
    run.repeatChange = reference::compareImages(second, run.image).relRmse;
    return run;
}

namespace {

void dump(const HardCase& c, const char* what, const assets::RgbImage& image) {
    const char* folder = std::getenv("NIMBUS_STABILITY_DUMP");
    if (folder == nullptr || *folder == '\0') return;
    std::filesystem::create_directories(folder);
    assets::writeImage(std::filesystem::path(folder) / (c.name + "_" + what + ".exr"), image);
}

}  // namespace

const CaseRun& runCase(gpu::Context& context, const HardCase& c) {
    static std::map<std::string, std::unique_ptr<CaseRun>> memo;
    if (auto it = memo.find(c.name); it != memo.end()) return *it->second;
    auto run = std::make_unique<CaseRun>();

    const std::filesystem::path scene = c.scene.is_absolute() ? c.scene : sceneDirectory() / c.scene;
    sandbox::Session session({.scene = scene, .time = c.time, .settings = c.settings, .scattering = assets::Scattering::Single});
    run->reference = renderReference(session, c.camera, c.width, c.height);
    const assets::RgbImage half = renderReference(session, c.camera, c.width, c.height, 0.5 * kReferenceTolerance);
    run->referenceNonfinite = countNonfinite(run->reference);
    run->referenceHalfNonfinite = countNonfinite(half);
    run->referenceSelfChange = relativeRmsChange(half, run->reference);
    run->referenceSparsity = sparsity(run->reference);
    run->particles = runTier(context, session, c, Tier::Particles, run->reference);
    run->blocks = runTier(context, session, c, Tier::Blocks, run->reference);
    run->balanced = runTier(context, session, c, Tier::Balanced, run->reference);
    run->fast = runTier(context, session, c, Tier::Fast, run->reference);
    run->particleCount = run->particles.stats.particles;

    std::printf("[stability] %-34s %7zu particles  rel_rmse particles %.4g  blocks %.4g  balanced %.4g  fast %.4g  "
                "(reference self-change %.2g; repeat %.2g / %.2g)\n",
                c.name.c_str(), run->particleCount, run->particles.error.relRmse, run->blocks.error.relRmse,
                run->balanced.error.relRmse, run->fast.error.relRmse, run->referenceSelfChange, run->particles.repeatChange,
                run->blocks.repeatChange);
    if (run->referenceSparsity >= kSparseImageRatio)
        std::printf("[stability] %-34s sparse (RMS %.3g x mean): bound on RMS-relative error, particles %.4g  blocks %.4g  "
                    "balanced %.4g  fast %.4g\n",
                    c.name.c_str(), run->referenceSparsity, run->particles.rmsRelativeError, run->blocks.rmsRelativeError,
                    run->balanced.rmsRelativeError, run->fast.rmsRelativeError);
    ::testing::Test::RecordProperty("rel_rmse_particles", std::to_string(run->particles.error.relRmse));
    ::testing::Test::RecordProperty("rel_rmse_blocks", std::to_string(run->blocks.error.relRmse));
    ::testing::Test::RecordProperty("rel_rmse_balanced", std::to_string(run->balanced.error.relRmse));
    ::testing::Test::RecordProperty("rel_rmse_fast", std::to_string(run->fast.error.relRmse));
    dump(c, "reference", run->reference);
    for (const Tier tier : kAllTiers) dump(c, tierName(tier), run->tier(tier).image);
    return *memo.emplace(c.name, std::move(run)).first->second;
}

std::size_t settledResidentBytes() {
    glFinish();
    malloc_trim(0);
    std::ifstream statm("/proc/self/statm");
    std::size_t size = 0, resident = 0;
    statm >> size >> resident;
    return resident * static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
}

std::unique_ptr<gpu::Context> createContext() { return gpu::Context::create({.debug = gpu::ContextDesc::Debug::On}); }

void StabilityTest::SetUp() {
    context_->makeCurrent();
    (void)context_->takeGlErrors();
}

void expectFiniteAndClean(const HardCase& c, const CaseRun& run) {
    SCOPED_TRACE(c.name);
    EXPECT_EQ(run.referenceNonfinite, 0u) << "reference has non-finite pixels";
    EXPECT_EQ(run.referenceHalfNonfinite, 0u) << "reference at half tolerance has non-finite pixels";
    EXPECT_LT(run.referenceSelfChange, kReferenceSelfChangeBound) << "the reference is not converged";
    for (const Tier tier : kAllTiers) {
        const ModeRun* m = &run.tier(tier);
        const char* mode = tierName(tier);
        EXPECT_EQ(m->nonfinite, 0u) << mode << ": non-finite pixels";
        EXPECT_EQ(m->repeatNonfinite, 0u) << mode << ": non-finite pixels in the second frame";
        EXPECT_EQ(m->glErrors.count, 0u) << mode << ": GL error: " << m->glErrors.first;
        EXPECT_LE(m->repeatChange, 1e-6) << mode << ": a second frame of the same state differs";
        EXPECT_EQ(m->stats.particles, run.particleCount) << mode << ": drew a different particle count";
    }
}

void expectWithinBound(const HardCase& c, const CaseRun& run, MediaMode mode, double bound) {
    expectWithinBound(c, run, mode == MediaMode::Blocks ? Tier::Blocks : Tier::Particles, bound);
}

void expectWithinBound(const HardCase& c, const CaseRun& run, Tier tier, double bound) {
    const ModeRun& m = run.tier(tier);
    const bool sparse = run.referenceSparsity >= kSparseImageRatio;
    EXPECT_LE(boundedError(run, tier), bound)
        << c.name << ", " << tierName(tier) << ": " << (sparse ? "RMS-relative error" : "rel-RMSE")
        << " against the reference " << boundedError(run, tier) << " (rel-RMSE " << m.error.relRmse << ", RMS-relative "
        << m.rmsRelativeError << ", reference RMS / mean " << run.referenceSparsity << ", p99 |diff| " << m.error.p99Abs << ")";
    EXPECT_EQ(m.error.comparedPixels, run.reference.pixelCount()) << c.name << ": some pixels were not comparable";
}

}  // namespace nimbus::stability
