#pragma once
// Test helpers for blocks mode: seeded particle clouds and cameras built in memory.
#include <cmath>
#include <random>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "nimbus/gpu/view.h"
#include "nimbus/media/particle_set.h"

namespace nimbus::media::test {

// A cumulus-like blob (tools/scenegen/make_scenes.py blob_cloud): `n` particles uniformly inside
// the ellipsoid `radii` around `centre`, radii in [rMin, rMax], peak extinction in [0.5, 1.5]·sigma.
inline ParticleSet blobCloud(std::size_t n, unsigned seed, const glm::dvec3& centre = glm::dvec3(0.0, 4.0, 0.0),
                             const glm::dvec3& radii = glm::dvec3(3.6, 1.8, 2.6), float rMin = 0.9f, float rMax = 1.5f,
                             float sigma = 0.8f) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    ParticleSet set;
    Medium medium;
    medium.albedo = glm::vec3(0.9f);
    while (set.size() < n) {
        const double z = u(rng), y = u(rng), x = u(rng);  // in sequence: the same cloud from every compiler
        const glm::dvec3 p(x, y, z);
        if (glm::dot(p, p) > 1.0) continue;
        const float r = rMin + static_cast<float>(0.5 * (u(rng) + 1.0)) * (rMax - rMin);
        const float s = sigma * static_cast<float>(1.0 + 0.5 * u(rng));
        set.push(centre + p * radii, r, s, medium);
    }
    return set;
}

// A perspective camera at `eye` looking at `target` (+Y up), infinite far plane.
struct TestCamera {
    glm::dmat4 world{1.0};
    double yfov = 0.7;
    double znear = 0.1;
};
inline TestCamera lookAtCamera(const glm::dvec3& eye, const glm::dvec3& target, double yfov = 0.7, double znear = 0.1) {
    return {glm::inverse(glm::lookAt(eye, target, glm::dvec3(0.0, 1.0, 0.0))), yfov, znear};
}
inline gpu::View makeView(const TestCamera& camera, int width, int height) {
    return gpu::makePerspectiveView(gpu::cameraPose(camera.world), camera.yfov, camera.znear, 0.0, width, height);
}

}  // namespace nimbus::media::test
