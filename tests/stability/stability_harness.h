#pragma once
// The hard-case harness (tests/stability/): one scene, one camera, one time, rendered by the CPU
// reference (twice: at its tolerance and at half of it) and by the real-time renderer in both media
// modes (each twice, from the same state), with everything the assertions need measured once:
//
//   - non-finite pixels of every image (NaN or Inf in any channel),
//   - GL errors while each mode rendered (KHR_debug on, plus glGetError),
//   - rel-RMSE of each mode against the reference (media::reference::compareImages),
//   - how much the reference changes when its tolerance is halved (its own stability), as
//     RMS(change) / RMS(reference): relative to the image's own RMS rather than its mean luminance,
//     because a per-pixel relative tolerance then bounds it (an image whose mean is 1000× below its
//     peak, e.g. g = 0.99 looking into the sun on black, would otherwise read 1e-4 as 0.1),
//   - how much a mode's second frame of the same state differs from its first (repeatability).
//
// Cases are memoised per process, so the "stays finite" and "within bound" tests of one case share
// one run. Every run prints one line with its numbers (the report's measured values).
//
// Does not: assert anything (the tests do), or write images unless $NIMBUS_STABILITY_DUMP names a
// folder (then <case>_{reference,particles,blocks}.exr are written there, to look at a failure).
#include <gtest/gtest.h>

#include <cstddef>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "nimbus/assets/image_io.h"
#include "nimbus/gpu/context.h"
#include "nimbus/media/media_renderer.h"
#include "nimbus/media/reference/image_metrics.h"
#include "session.h"

namespace nimbus::stability {

// The two modes every hard case runs in, by their names in the technique table.
enum class MediaMode { Particles, Blocks };
inline const char* mediaModeName(MediaMode mode) { return mode == MediaMode::Blocks ? "blocks" : "particles"; }

// The reference's default tolerance (ReferenceSettings) and the bound on how much halving it may
// change the image: the judge must be converged far below the real-time errors it judges.
inline constexpr double kReferenceTolerance = 1e-4;
inline constexpr double kReferenceSelfChangeBound = 1e-3;
// The default bound on real-time error against the reference.
inline constexpr double kDefaultErrorBound = 0.15;
// Where the reference's RMS is this many times its mean luminance, its light lies in a few of its
// pixels (RMS / mean ≈ 1/√f for light in a fraction f of them: 5 is 4%), and rel-RMSE reads a
// relative error e of those pixels as about 5e, so 3% there already meets the 15% bound. The
// bound then applies to RMS(error) / RMS(reference) instead (boundedError). A glory seen along
// the sun (g = −0.99) is 2–3% off at its peak in both modes and read 11.5% and 27% at a ratio of
// 9.9 (fresh stability seed 26 variant 08).
inline constexpr double kSparseImageRatio = 5.0;

struct HardCase {
    std::string name;                   // for messages, the printed line and dumped files
    std::filesystem::path scene;        // relative: under tests/data/stability_scenes
    std::string camera;                 // empty: the scene's first
    int width = 160, height = 90;
    double time = 0.0;                  // simulated to before rendering
    std::vector<std::string> settings;       // KEY=VALUE for both modes (e.g. "layer_light=off")
    std::vector<std::string> blockSettings;  // KEY=VALUE for the blocks tier alone (e.g. "blocks=26"): refused in particles
};

// What a real-time run renders: the exact tier in each mode, and `particles` in the balanced and
// fast tiers (the quality presets).
enum class Tier { Particles, Blocks, Balanced, Fast };
const char* tierName(Tier tier);
inline constexpr Tier kAllTiers[] = {Tier::Particles, Tier::Blocks, Tier::Balanced, Tier::Fast};

struct ModeRun {
    Tier tier = Tier::Particles;
    MediaMode mode = MediaMode::Particles;
    assets::RgbImage image;              // the first frame
    media::reference::ImageMetrics error;  // first frame against the reference
    double rmsRelativeError = 0.0;       // RMS(first frame − reference) / RMS(reference)
    std::size_t nonfinite = 0;           // non-finite pixels of the first frame
    double repeatChange = 0.0;           // rel-RMSE of the second frame against the first
    std::size_t repeatNonfinite = 0;
    gpu::GlErrorReport glErrors;         // during both frames
    media::MediaFrameStats stats;        // of the last frame (zeros when nothing was drawn)
};

struct CaseRun {
    assets::RgbImage reference;
    std::size_t referenceNonfinite = 0;
    double referenceSelfChange = 0.0;    // RMS(half-tolerance image − first) / RMS(first)
    double referenceSparsity = 0.0;      // RMS(reference) / its mean luminance (see kSparseImageRatio)
    std::size_t referenceHalfNonfinite = 0;
    std::size_t particleCount = 0;       // what both renderers drew
    ModeRun particles, blocks, balanced, fast;
    const ModeRun& mode(MediaMode m) const { return m == MediaMode::Blocks ? blocks : particles; }
    const ModeRun& tier(Tier t) const {
        return t == Tier::Blocks ? blocks : t == Tier::Balanced ? balanced : t == Tier::Fast ? fast : particles;
    }
};

// tests/data/stability_scenes (compiled in by nimbus_test's NIMBUS_TEST_DATA_DIR).
std::filesystem::path sceneDirectory();

// Non-finite pixels of an image (any channel NaN or Inf).
std::size_t countNonfinite(const assets::RgbImage& image);

// RMS(a − b) / RMS(b) over all channels (0 when both are identical, +inf when b is 0 and a is not).
double relativeRmsChange(const assets::RgbImage& a, const assets::RgbImage& b);

// RMS over all channels / mean Rec.709 luminance (0 for a black image).
double sparsity(const assets::RgbImage& image);

// The error a mode's bound applies to: its rel-RMSE against the reference, except where the
// reference is sparse (kSparseImageRatio): there rel-RMSE, whose denominator is the mean
// luminance, reads a relative error e of the few lit pixels as e·RMS/mean (one lit pixel of
// 160×90: 120·e, so a 0.2% error fails 15%), and RMS(error) / RMS(reference) reads it as e. The
// harness measures the reference's own convergence that way for the same reason.
double boundedError(const CaseRun& run, MediaMode mode);
double boundedError(const CaseRun& run, Tier tier);

// The reference of a session's current state at width×height through `camera`.
assets::RgbImage renderReference(sandbox::Session& session, const std::string& camera, int width, int height,
                                 double tolerance = kReferenceTolerance);

// One real-time frame in `tier` (sets the session's "mode" and "quality" settings).
assets::RgbImage renderTier(sandbox::Session& session, Tier tier, int width, int height, const std::string& camera);

inline Tier exactTier(MediaMode mode) { return mode == MediaMode::Blocks ? Tier::Blocks : Tier::Particles; }
// One frame of the exact tier in `mode`.
inline assets::RgbImage renderMode(sandbox::Session& session, MediaMode mode, int width, int height, const std::string& camera) {
    return renderTier(session, exactTier(mode), width, height, camera);
}

// One tier of the session's current state (two frames) against `reference`.
ModeRun runTier(gpu::Context& context, sandbox::Session& session, const HardCase& c, Tier tier, const assets::RgbImage& reference);
inline ModeRun runMode(gpu::Context& context, sandbox::Session& session, const HardCase& c, MediaMode mode,
                       const assets::RgbImage& reference) {
    return runTier(context, session, c, exactTier(mode), reference);
}

// Everything for one case (memoised by name). Needs the suite's context current.
const CaseRun& runCase(gpu::Context& context, const HardCase& c);

// The frame's media statistics (zeros when the media renderer does not exist yet).
media::MediaFrameStats mediaStats(sandbox::Session& session);

// Resident set size of this process, bytes (/proc/self/statm), after glFinish() and malloc_trim(0):
// llvmpipe keeps GL buffers and textures in process memory (so this counts them), frees some of
// them asynchronously, and freed heap pages would otherwise stay resident. Even so, llvmpipe's own
// per-frame memory (binned triangles of 10⁶ instanced quads) makes it vary by up to ~50 MB from
// one frame to the next of the same state.
std::size_t settledResidentBytes();

// One headless GL context per suite, with KHR_debug on so GL errors are counted in every build.
// llvmpipe runs with its default rasteriser threads, so that races between buffer updates and
// queued draws show up (realtime_repeatability_test.cpp).
std::unique_ptr<gpu::Context> createContext();

class StabilityTest : public ::testing::Test {
protected:
    static void SetUpTestSuite() { context_ = createContext(); }
    static void TearDownTestSuite() { context_.reset(); }
    void SetUp() override;
    static gpu::Context& context() { return *context_; }

private:
    static inline std::unique_ptr<gpu::Context> context_;
};

// The assertions every hard case makes, in two groups so that a case whose error is beyond its
// bound still checks that it stays finite (the bound test is the one DISABLED_ until fixed).
//   expectFiniteAndClean: no non-finite pixel in the reference (both tolerances) or in any tier's
//     two frames; no GL error in any tier; halving the reference's tolerance changes it by < 1e-3
//     (relativeRmsChange); a second frame of the same state is identical; every tier drew the same
//     particles.
//   expectWithinBound: rel-RMSE of `mode` (the exact tier) or `tier` against the reference <= bound.
void expectFiniteAndClean(const HardCase& c, const CaseRun& run);
void expectWithinBound(const HardCase& c, const CaseRun& run, MediaMode mode, double bound);
void expectWithinBound(const HardCase& c, const CaseRun& run, Tier tier, double bound);

}  // namespace nimbus::stability
