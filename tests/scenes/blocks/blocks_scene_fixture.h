#pragma once
// Test helpers for blocks-mode scene tests: real-time frames and the CPU reference of one scene
// through sandbox::Session (exactly what `sandbox render` / `sandbox reference` compute), and the
// band of pixels where a thin mesh cuts the cloud, found from geometry alone.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "nimbus/assets/image_io.h"
#include "nimbus/media/ecs/media_plugin.h"
#include "nimbus/media/reference/camera_rays.h"
#include "nimbus/media/reference/image_metrics.h"
#include "nimbus/media/reference/reference_renderer.h"
#include "nimbus/raycast/mesh_raycaster.h"
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

// Per pixel (row-major, 1/0): whether its camera ray first hits a mesh of node `meshNode`, and
// with `insideParticles`, at a point inside at least one particle's sphere (where a particle's
// billboard plane can cut the mesh).
inline std::vector<char> meshPixels(const std::filesystem::path& scene, int width, int height, const std::string& meshNode,
                                    bool insideParticles) {
    sandbox::Session session({.scene = scene});
    const auto ref = sandbox::makeReferenceScene(session, "", width, height);
    const raycast::MeshRaycaster raycaster(session.scene(), ref->world);
    const media::reference::CameraFrame frame = media::reference::makeCameraFrame(ref->inputs.camera, width, height);
    const media::ParticleSet& particles = ref->particles;
    std::vector<char> pixels(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), 0);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const media::reference::CameraRay ray = media::reference::cameraRay(frame, x, y);
            const auto hit = raycaster.closestHit(ray.origin, ray.direction, ray.meshNear, ray.meshFar);
            if (!hit || session.scene().nodes[static_cast<std::size_t>(hit->node)].name != meshNode) continue;
            bool inside = !insideParticles;
            for (std::size_t i = 0; i < particles.size() && !inside; ++i) {
                const double r = particles.radius[i];
                inside = glm::dot(hit->position - particles.position[i], hit->position - particles.position[i]) < r * r;
            }
            pixels[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)] = inside ? 1 : 0;
        }
    return pixels;
}

// The row-major indices of the pixels within `dilate` pixels (Chebyshev) of a set pixel of `pixels`.
inline std::vector<std::size_t> dilatedPixels(const std::vector<char>& pixels, int width, int height, int dilate) {
    std::vector<std::size_t> near;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            bool found = false;
            for (int dy = -dilate; dy <= dilate && !found; ++dy)
                for (int dx = -dilate; dx <= dilate && !found; ++dx) {
                    const int sx = x + dx, sy = y + dy;
                    found = sx >= 0 && sy >= 0 && sx < width && sy < height &&
                            pixels[static_cast<std::size_t>(sy) * static_cast<std::size_t>(width) + static_cast<std::size_t>(sx)] != 0;
                }
            if (found) near.push_back(static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x));
        }
    return near;
}

// The seam band: pixels whose camera ray first hits a mesh of node `meshNode` at a point inside at
// least one particle's sphere (where a particle's billboard plane can cut the mesh), dilated by
// `dilate` pixels (Chebyshev). Row-major pixel indices.
inline std::vector<std::size_t> seamBand(const std::filesystem::path& scene, int width, int height, const std::string& meshNode,
                                         int dilate, std::size_t* seamPixels = nullptr) {
    const std::vector<char> seam = meshPixels(scene, width, height, meshNode, true);
    if (seamPixels != nullptr) *seamPixels = static_cast<std::size_t>(std::count(seam.begin(), seam.end(), char{1}));
    return dilatedPixels(seam, width, height, dilate);
}

// image_metrics.h's rel_rmse over a subset of pixels: RMSE of linear RGB over those pixels / mean
// luminance of the reference over them.
inline double relRmseOver(const assets::RgbImage& image, const assets::RgbImage& reference, const std::vector<std::size_t>& pixels) {
    const int n = static_cast<int>(pixels.size());
    assets::RgbImage a(n, 1), b(n, 1);
    for (int k = 0; k < n; ++k) {
        const int x = static_cast<int>(pixels[static_cast<std::size_t>(k)] % static_cast<std::size_t>(image.width));
        const int y = static_cast<int>(pixels[static_cast<std::size_t>(k)] / static_cast<std::size_t>(image.width));
        a.set(k, 0, image.at(x, y));
        b.set(k, 0, reference.at(x, y));
    }
    return media::reference::compareImages(a, b).relRmse;
}

inline double relRmse(const assets::RgbImage& image, const assets::RgbImage& reference) {
    return media::reference::compareImages(image, reference).relRmse;
}

}  // namespace nimbus::test
