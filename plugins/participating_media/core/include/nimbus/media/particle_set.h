#pragma once
// The medium as the renderers see it: every particle of every medium in the scene, in world space,
// as structure-of-arrays. Both the reference and the real-time passes read this one set, so they
// render exactly the same state (docs/design.md §2).
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace nimbus::media {

enum class PhaseFunction : std::uint8_t { HenyeyGreenstein = 0, Rayleigh = 1 };

// Optical properties of one medium (the node's "medium" object, docs/design.md §4).
struct Medium {
    float extinction = 1.0f;        // σ, 1/m, > 0
    glm::vec3 albedo{1.0f};         // single-scattering albedo, each in [0, 1]
    float g = 0.0f;                 // Henyey–Greenstein asymmetry, in (-1, 1)
    glm::vec3 emission{0.0f};       // emitted radiance per unit optical depth (fire), >= 0
    PhaseFunction phase = PhaseFunction::HenyeyGreenstein;
};

// Particle i: centre, radius R, peak extinction sigma (σ·density, 1/m), albedo, emission, g, phase.
// Kernel: ρ(r) = exp(-4.5 r²/R²) for r < R, else 0.
struct ParticleSet {
    std::vector<glm::dvec3> position;  // world space, double so scenes far from the origin stay exact
    std::vector<float> radius;
    std::vector<float> sigma;
    std::vector<glm::vec3> albedo;
    std::vector<glm::vec3> emission;
    std::vector<float> g;
    std::vector<PhaseFunction> phase;

    std::size_t size() const { return position.size(); }
    bool empty() const { return position.empty(); }
    void clear();
    void reserve(std::size_t n);
    void push(const glm::dvec3& p, float r, float s, const Medium& medium);
    void append(const ParticleSet& other);
};

}  // namespace nimbus::media
