#pragma once
// The viewport's Reference snapshot: `sandbox reference` of the current view and time, rendered on
// background threads while the UI runs, then judged against the real-time frame it was started
// beside with `sandbox compare`'s metrics and a heat map of the per-pixel error.
// With multiple scattering it is progressive: rounds of paths with their own seeds, each doubling
// the paths per pixel so far, and after each the picture, its noise and its error are shown. The
// rounds are independent unbiased estimates, so their path-weighted mean is one too.
//
// Does not: render when nothing changed since the last snapshot, or survive an edit (the editor
// cancels it: the frame it judged is gone).
#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "nimbus/assets/image_io.h"
#include "nimbus/media/reference/image_metrics.h"
#include "nimbus/media/reference/reference_renderer.h"
#include "session.h"

namespace nimbus::sandbox::editor {

class ReferenceSnapshot {
public:
    ReferenceSnapshot() = default;
    ~ReferenceSnapshot();
    ReferenceSnapshot(const ReferenceSnapshot&) = delete;
    ReferenceSnapshot& operator=(const ReferenceSnapshot&) = delete;

    // Starts a snapshot of `session`'s state as `realtime` shows it through `camera` (the free
    // camera when `cameraOverride` is set). `revision` ties it to what the viewport shows.
    // `paths`: the paths per pixel at which it stops (multiple scattering).
    void start(Session& session, const std::string& camera, const assets::ResolvedCamera* cameraOverride,
               const assets::RgbImage& realtime, std::uint64_t revision, int paths = kDefaultPaths);
    void cancel();   // stops the threads; the snapshot is dropped
    void stop();     // stops the threads; the rounds finished so far stay
    void update();   // call once per frame: picks up each finished round

    static constexpr int kDefaultPaths = 64;  // `sandbox reference`'s --spp default

    bool running() const { return worker_.joinable() && !finished_; }
    bool ready() const { return result_ != nullptr; }
    double progress() const;  // 0..1 of the round under way
    std::uint64_t revision() const { return revision_; }

    struct Result {
        assets::RgbImage reference;
        assets::RgbImage realtime;
        media::reference::ImageMetrics metrics;
        assets::RgbImage heat;  // |realtime − reference| luminance relative to the reference mean, colour-mapped
        double seconds = 0.0;
        int paths = 0;                  // per pixel so far; 0 with single scattering (no paths)
        double relativeNoise = 0.0;     // mean standard error of luminance over mean luminance
    };
    const Result* result() const { return result_.get(); }

private:
    void join();
    void renderRounds(const media::reference::ReferenceSettings& settings, int paths);
    void publish(const assets::RgbImage& sum, const assets::RgbImage& variance, int paths, double seconds);

    std::thread worker_;
    std::atomic<bool> finished_{false};
    media::reference::ReferenceProgress progress_;
    std::mutex mutex_;                  // guards pending_: the worker publishes, update() takes
    std::unique_ptr<Result> pending_, result_;
    assets::RgbImage realtime_;
    std::shared_ptr<const assets::Scene> scene_;
    std::unique_ptr<ReferenceScene> inputs_;
    std::uint64_t revision_ = 0;
};

// The heat map's colours: 0 black, 1% blue, 5% green, 20% and above red (relative to mean luminance).
assets::RgbImage errorHeatMap(const assets::RgbImage& realtime, const assets::RgbImage& reference);

}  // namespace nimbus::sandbox::editor
