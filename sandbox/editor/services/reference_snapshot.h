#pragma once
// The viewport's Reference snapshot: `sandbox reference` of the current view and time, rendered on
// background threads while the UI runs, then judged against the real-time frame it was started
// beside with `sandbox compare`'s metrics and a heat map of the per-pixel error.
//
// Does not: render when nothing changed since the last snapshot, or survive an edit (the editor
// cancels it: the frame it judged is gone).
#include <atomic>
#include <cstdint>
#include <memory>
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
    void start(Session& session, const std::string& camera, const assets::ResolvedCamera* cameraOverride,
               const assets::RgbImage& realtime, std::uint64_t revision);
    void cancel();   // stops the threads; the snapshot is dropped
    void update();   // call once per frame: picks up a finished render

    bool running() const { return worker_.joinable() && !finished_; }
    bool ready() const { return result_ != nullptr; }
    double progress() const;  // 0..1 while running
    std::uint64_t revision() const { return revision_; }

    struct Result {
        assets::RgbImage reference;
        assets::RgbImage realtime;
        media::reference::ImageMetrics metrics;
        assets::RgbImage heat;  // |realtime − reference| luminance relative to the reference mean, colour-mapped
        double seconds = 0.0;
    };
    const Result* result() const { return result_.get(); }

private:
    void join();

    std::thread worker_;
    std::atomic<bool> finished_{false};
    media::reference::ReferenceProgress progress_;
    std::unique_ptr<Result> pending_, result_;
    std::shared_ptr<const assets::Scene> scene_;
    std::unique_ptr<ReferenceScene> inputs_;
    std::uint64_t revision_ = 0;
};

// The heat map's colours: 0 black, 1% blue, 5% green, 20% and above red (relative to mean luminance).
assets::RgbImage errorHeatMap(const assets::RgbImage& realtime, const assets::RgbImage& reference);

}  // namespace nimbus::sandbox::editor
