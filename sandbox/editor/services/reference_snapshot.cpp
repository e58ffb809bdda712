#include "reference_snapshot.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace nimbus::sandbox::editor {

using media::reference::luminance;

ReferenceSnapshot::~ReferenceSnapshot() { cancel(); }

void ReferenceSnapshot::join() {
    if (worker_.joinable()) worker_.join();
    finished_ = false;
}

void ReferenceSnapshot::cancel() {
    progress_.cancel = true;
    join();
    pending_.reset();
    result_.reset();
    inputs_.reset();
    scene_.reset();
}

void ReferenceSnapshot::start(Session& session, const std::string& camera, const assets::ResolvedCamera* cameraOverride,
                              const assets::RgbImage& realtime, std::uint64_t revision) {
    cancel();
    progress_.cancel = false;
    progress_.tilesDone = 0;
    progress_.tilesTotal = 0;
    revision_ = revision;
    scene_ = session.sharedScene();  // the inputs point into it
    inputs_ = makeReferenceScene(session, camera, realtime.width, realtime.height, cameraOverride);
    media::reference::ReferenceSettings settings;
    settings.width = realtime.width;
    settings.height = realtime.height;
    settings.progress = false;
    settings.watch = &progress_;
    pending_ = std::make_unique<Result>();
    pending_->realtime = realtime;
    worker_ = std::thread([this, settings] {
        const auto begin = std::chrono::steady_clock::now();
        pending_->reference = media::reference::renderReference(inputs_->inputs, settings);
        pending_->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
        finished_ = true;
    });
}

void ReferenceSnapshot::update() {
    if (!worker_.joinable() || !finished_) return;
    join();
    if (progress_.cancel) return;
    pending_->metrics = media::reference::compareImages(pending_->realtime, pending_->reference);
    pending_->heat = errorHeatMap(pending_->realtime, pending_->reference);
    result_ = std::move(pending_);
}

double ReferenceSnapshot::progress() const {
    const int total = progress_.tilesTotal.load();
    return total > 0 ? static_cast<double>(progress_.tilesDone.load()) / total : 0.0;
}

assets::RgbImage errorHeatMap(const assets::RgbImage& realtime, const assets::RgbImage& reference) {
    double mean = 0.0;
    for (std::size_t i = 0; i < reference.pixelCount(); ++i)
        mean += luminance(reference.rgb[3 * i], reference.rgb[3 * i + 1], reference.rgb[3 * i + 2]);
    mean = std::max(mean / static_cast<double>(std::max<std::size_t>(1, reference.pixelCount())), 1e-12);
    assets::RgbImage heat(reference.width, reference.height);
    for (std::size_t i = 0; i < reference.pixelCount(); ++i) {
        const double d = std::abs(luminance(realtime.rgb[3 * i] - reference.rgb[3 * i], realtime.rgb[3 * i + 1] - reference.rgb[3 * i + 1],
                                            realtime.rgb[3 * i + 2] - reference.rgb[3 * i + 2])) / mean;
        // Log scale from 0.1% (dark) through 1% (blue) and 5% (green) to 20% (red).
        const double t = std::isfinite(d) ? std::clamp((std::log10(std::max(d, 1e-3)) + 3.0) / (std::log10(0.2) + 3.0), 0.0, 1.0) : 1.0;
        const float r = static_cast<float>(std::clamp(3.0 * t - 2.0, 0.0, 1.0));
        const float g = static_cast<float>(std::clamp(1.0 - std::abs(3.0 * t - 2.0), 0.0, 1.0));
        const float b = static_cast<float>(std::clamp(1.0 - std::abs(3.0 * t - 1.0), 0.0, 1.0) * (t > 0.0 ? 1.0 : 0.0));
        heat.rgb[3 * i] = r;
        heat.rgb[3 * i + 1] = g;
        heat.rgb[3 * i + 2] = b;
    }
    return heat;
}

}  // namespace nimbus::sandbox::editor
