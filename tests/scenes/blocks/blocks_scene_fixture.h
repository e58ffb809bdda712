#pragma once
// Test helpers for blocks-mode scene tests: real-time frames and the CPU reference of one scene
// through sandbox::Session (exactly what `sandbox render` / `sandbox reference` compute); the band
// of pixels where a thin mesh cuts the cloud is ../seam_band.h's.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "nimbus/assets/image_io.h"
#include "nimbus/media/ecs/media_plugin.h"
#include "nimbus/media/reference/image_metrics.h"
#include "nimbus/media/reference/reference_renderer.h"
#include "seam_band.h"
#include "session.h"

namespace nimbus::test {

// One real-time frame of `scene` at t = 0 with the given --set assignments ("mode=blocks", ...).
// Needs a current GL context. `blocks`, when given, receives the block count the renderer used.
inline assets::RgbImage renderRealtime(const std::filesystem::path& scene, int width, int height,
                                       const std::vector<std::string>& settings, int* blocks = nullptr) {
    sandbox::Session session({.scene = scene, .time = 0.0, .settings = settings, .scattering = assets::Scattering::Single});
    assets::RgbImage image = session.renderRealtime(width, height);
    if (blocks != nullptr) {
        const auto& state = session.app().resource<media::ecs::MediaRendererState>();
        *blocks = state.renderer ? static_cast<int>(state.renderer->stats().value("blocks", -1)) : -1;
    }
    return image;
}

// The CPU reference of `scene` at t = 0 (two threads: the test machine's cores).
inline assets::RgbImage renderReference(const std::filesystem::path& scene, int width, int height) {
    sandbox::Session session({.scene = scene});
    const auto inputs = sandbox::makeReferenceScene(session, "", width, height);
    media::reference::ReferenceSettings settings;
    settings.scattering = assets::Scattering::Single;  // today's real-time model
    settings.width = width;
    settings.height = height;
    settings.threads = 2;
    settings.progress = false;
    return media::reference::renderReference(inputs->inputs, settings);
}

inline double relRmse(const assets::RgbImage& image, const assets::RgbImage& reference) {
    return media::reference::compareImages(image, reference).relRmse;
}

}  // namespace nimbus::test
