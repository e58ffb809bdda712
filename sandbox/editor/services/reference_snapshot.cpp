#include "reference_snapshot.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>

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

void ReferenceSnapshot::stop() {
    update();  // a round finished since the last frame counts
    progress_.cancel = true;
    join();
    pending_.reset();
}

void ReferenceSnapshot::start(Session& session, const std::string& camera, const assets::ResolvedCamera* cameraOverride,
                              const assets::RgbImage& realtime, std::uint64_t revision, int paths) {
    cancel();
    progress_.cancel = false;
    progress_.tilesDone = 0;
    progress_.tilesTotal = 0;
    revision_ = revision;
    scene_ = session.sharedScene();  // the inputs point into it
    inputs_ = makeReferenceScene(session, camera, realtime.width, realtime.height, cameraOverride);
    realtime_ = realtime;
    media::reference::ReferenceSettings settings;
    settings.width = realtime.width;
    settings.height = realtime.height;
    settings.progress = false;
    settings.watch = &progress_;
    worker_ = std::thread([this, settings, paths] {
        renderRounds(settings, paths);
        finished_ = true;
    });
}

// Rounds of 4, 4, 8, 16, ... paths per pixel (seeds 1, 2, ...) until `paths` in all; one round when
// nothing is path traced.
void ReferenceSnapshot::renderRounds(const media::reference::ReferenceSettings& base, int paths) {
    const auto begin = std::chrono::steady_clock::now();
    assets::RgbImage sum(base.width, base.height), variance(base.width, base.height);
    int done = 0;
    for (std::uint64_t round = 1; !progress_.cancel; ++round) {
        media::reference::ReferenceSettings settings = base;
        settings.spp = std::min(std::max(done, 4), paths - done);
        settings.seed = round;
        progress_.tilesDone = 0;
        const media::reference::ReferenceRenderer renderer(inputs_->inputs, settings);
        assets::RgbImage error;
        const assets::RgbImage image = renderer.render(nullptr, &error);
        if (progress_.cancel) return;
        const bool multiple = renderer.multiple();
        const float n = static_cast<float>(settings.spp);
        for (std::size_t i = 0; i < sum.rgb.size(); ++i) {  // the mean of n paths counts n times; its variance n² times
            sum.rgb[i] += (multiple ? n : 1.0f) * image.rgb[i];
            variance.rgb[i] += multiple ? n * n * error.rgb[i] * error.rgb[i] : 0.0f;
        }
        done = multiple ? done + settings.spp : 0;
        publish(sum, variance, done, std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count());
        if (!multiple || done >= paths) return;
    }
}

void ReferenceSnapshot::publish(const assets::RgbImage& sum, const assets::RgbImage& variance, int paths, double seconds) {
    auto result = std::make_unique<Result>();
    result->realtime = realtime_;
    result->reference = sum;
    const float scale = paths > 0 ? 1.0f / static_cast<float>(paths) : 1.0f;
    double noise = 0.0, mean = 0.0;
    for (std::size_t i = 0; i < sum.pixelCount(); ++i) {
        float* rgb = &result->reference.rgb[3 * i];
        for (int c = 0; c < 3; ++c) rgb[c] *= scale;
        mean += luminance(rgb[0], rgb[1], rgb[2]);
        noise += luminance(std::sqrt(variance.rgb[3 * i]), std::sqrt(variance.rgb[3 * i + 1]), std::sqrt(variance.rgb[3 * i + 2])) * scale;
    }
    result->paths = paths;
    result->relativeNoise = mean > 0.0 ? noise / mean : 0.0;
    result->seconds = seconds;
    const std::lock_guard<std::mutex> lock(mutex_);
    pending_ = std::move(result);
}

void ReferenceSnapshot::update() {
    std::unique_ptr<Result> next;
    {
        const std::lock_guard<std::mutex> lock(mutex_);
        next = std::move(pending_);
    }
    if (next && !progress_.cancel) {
        next->metrics = media::reference::compareImages(next->realtime, next->reference);
        next->heat = errorHeatMap(next->realtime, next->reference);
        result_ = std::move(next);
    }
    if (worker_.joinable() && finished_) join();
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
