#pragma once
// The seam band of a scene: the pixels where a mesh cuts the medium, found from geometry alone (the
// reference's camera rays and a mesh ray caster, no renderer), and rel-RMSE over a set of pixels.
// Used by the blocks and the media seam tests.
#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "nimbus/assets/image_io.h"
#include "nimbus/media/reference/camera_rays.h"
#include "nimbus/media/reference/image_metrics.h"
#include "nimbus/raycast/mesh_raycaster.h"
#include "session.h"

namespace nimbus::test {

// Per pixel (row-major, 1/0): whether its camera ray first hits a mesh of node `meshNode` (empty:
// any mesh), and with `insideParticles`, at a point inside at least one particle's sphere (where a
// particle's billboard plane can cut the mesh).
inline std::vector<char> meshPixels(const std::filesystem::path& scene, int width, int height, const std::string& meshNode,
                                    bool insideParticles) {
    sandbox::Session session({.scene = scene});
    const auto ref = sandbox::makeReferenceScene(session, "", width, height);
    const raycast::MeshRaycaster raycaster(session.scene(), ref->world);
    const nimbus::media::reference::CameraFrame frame = nimbus::media::reference::makeCameraFrame(ref->inputs.camera, width, height);
    const nimbus::media::ParticleSet& particles = ref->particles;
    std::vector<char> pixels(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), 0);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const nimbus::media::reference::CameraRay ray = nimbus::media::reference::cameraRay(frame, x, y);
            const auto hit = raycaster.closestHit(ray.origin, ray.direction, ray.meshNear, ray.meshFar);
            if (!hit || (!meshNode.empty() && session.scene().nodes[static_cast<std::size_t>(hit->node)].name != meshNode)) continue;
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

// The seam band: pixels whose camera ray first hits a mesh of node `meshNode` (empty: any) at a point inside at
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
    return nimbus::media::reference::compareImages(a, b).relRmse;
}

}  // namespace nimbus::test
