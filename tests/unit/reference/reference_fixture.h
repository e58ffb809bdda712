#pragma once
// Test helper: an in-memory scene + particles + camera + lights, rendered by the reference, and
// brute-force numeric integrals along rays to judge it with.
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "nimbus/media/optics.h"
#include "nimbus/media/particle_set.h"
#include "nimbus/media/volume.h"
#include "nimbus/media/reference/camera_rays.h"
#include "nimbus/media/reference/reference_renderer.h"
#include "numeric_quadrature.h"
#include "scene_builder.h"

namespace nimbus::media::test {

struct TestScene {
    fixtures::SceneBuilder builder;
    ParticleSet particles;
    std::vector<Volume> volumes;
    assets::ResolvedCamera camera = fixtures::lookAt({0.0, 0.0, 10.0}, {0.0, 0.0, 0.0});
    std::vector<assets::ResolvedLight> lights;
    std::vector<glm::dmat4> world;

    reference::ReferenceInputs inputs() {
        world = builder.world();
        reference::ReferenceInputs in;
        in.scene = &builder.scene;
        in.world = &world;
        in.camera = camera;
        in.lights = lights;
        in.particles = &particles;
        in.volumes = &volumes;
        return in;
    }
};

inline reference::ReferenceSettings settings(int w, int h, double tolerance = 1e-4, int threads = 2) {
    reference::ReferenceSettings s;
    s.scattering = assets::Scattering::Single;  // the analytic cases of the single-scattering model
    s.width = w;
    s.height = h;
    s.tolerance = tolerance;
    s.threads = threads;
    s.progress = false;
    return s;
}

inline Medium medium(float albedo, float g = 0.0f, const glm::vec3& emission = glm::vec3(0.0f),
                     PhaseFunction phase = PhaseFunction::HenyeyGreenstein) {
    Medium m;
    m.albedo = glm::vec3(albedo);
    m.g = g;
    m.emission = emission;
    m.phase = phase;
    return m;
}

// A seeded random cloud inside the box [lo, hi].
inline void addRandomCloud(ParticleSet& set, std::size_t n, unsigned seed, const glm::dvec3& lo, const glm::dvec3& hi,
                           float rMin, float rMax, float sigma, const Medium& m) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (std::size_t i = 0; i < n; ++i) {
        const double z = u(rng), y = u(rng), x = u(rng);  // in sequence: the same cloud from every compiler
        const glm::dvec3 p = lo + (hi - lo) * glm::dvec3(x, y, z);
        set.push(p, rMin + static_cast<float>(u(rng)) * (rMax - rMin), sigma * static_cast<float>(0.5 + u(rng)), m);
    }
}

// Sorted chord endpoints of every particle on origin + t·dir within [0, end], plus 0 and end.
// An infinite end becomes the last chord exit (nothing lies beyond it).
inline std::vector<double> chordBreaks(const ParticleSet& set, const glm::dvec3& o, const glm::dvec3& d, double end) {
    std::vector<double> b = {0.0};
    double lastExit = 0.0;
    for (std::size_t i = 0; i < set.size(); ++i) {
        const ChordGeometry c = chordGeometry(o, d, set.position[i], set.radius[i]);
        if (!c.hit()) continue;
        lastExit = std::max(lastExit, c.tExit());
        for (double t : {c.tEnter(), c.tExit()})
            if (t > 0.0 && t < end) b.push_back(t);
    }
    b.push_back(std::isinf(end) ? lastExit : end);
    std::sort(b.begin(), b.end());
    b.erase(std::unique(b.begin(), b.end()), b.end());
    return b;
}

// σ_t at a point, summed over every particle (no acceleration: the judge of the judge).
inline long double extinction(const ParticleSet& set, const glm::dvec3& x) {
    long double s = 0.0L;
    for (std::size_t i = 0; i < set.size(); ++i) {
        const glm::dvec3 v = x - set.position[i];
        s += set.sigma[i] * kernelDensity(glm::dot(v, v), set.radius[i]);
    }
    return s;
}

// The particles whose sphere the line origin + t·dir crosses (brute force, to keep quadratures short).
inline ParticleSet particlesOnLine(const ParticleSet& set, const glm::dvec3& o, const glm::dvec3& d) {
    ParticleSet out;
    for (std::size_t i = 0; i < set.size(); ++i) {
        if (!chordGeometry(o, d, set.position[i], set.radius[i]).hit()) continue;
        Medium m;
        m.albedo = set.albedo[i];
        m.emission = set.emission[i];
        m.g = set.g[i];
        m.phase = set.phase[i];
        out.push(set.position[i], set.radius[i], set.sigma[i], m);
    }
    return out;
}

// τ along origin + t·dir over [0, end] by quadrature, piecewise between chord endpoints.
inline long double numericOpticalDepth(const ParticleSet& all, const glm::dvec3& o, const glm::dvec3& d, double end,
                                       int panels = 16) {
    const ParticleSet set = particlesOnLine(all, o, d);
    const std::vector<double> b = chordBreaks(set, o, d, end);
    long double tau = 0.0L;
    for (std::size_t k = 0; k + 1 < b.size(); ++k)
        tau += integrate([&](long double t) { return extinction(set, o + static_cast<double>(t) * d); }, b[k], b[k + 1], panels);
    return tau;
}

}  // namespace nimbus::media::test
