#pragma once
// The emitter system's simulation (docs/design.md §3, McReynolds and Blythe §9): spawns, moves, ages and recycles the
// particles of one emitter, in structure-of-arrays, with a fixed time step and a seeded RNG.
//
// Determinism: the state after a sequence of step() calls depends only on the EmitterDesc, the node
// index and the arguments of the calls. Two hosts that step the same way (same t0 = k·dt computed
// as a product, same dt, same matrices) get bit-identical particles; this is how `--time T` (the
// reference) renders exactly what the real-time path renders. Within one build: the spawn sampling
// uses the C library's cbrt/sqrt/sin/cos.
//
// Memory: every array reserves max_particles at construction and never grows. A particle dies when
// its age reaches its lifetime; the last particle is moved into its slot (swap-with-last, scanning
// upwards, so the order is a pure function of the history). Spawns while the pool is full are
// dropped (counted in droppedCount()).
//
// One step, for each live particle (semi-implicit Euler in double, h = dt):
//   v ← (v + buoyancy·ŷ·h) / (1 + drag·h)          (drag implicit: stable for any drag·h)
//   x ← x + h·(v + wind + turbulence(x, t0))       (wind and curl noise advect; they are the air)
//   age ← age + h
// Newborns get a birth time tb inside [t0, t0+dt): start + m/rate for the m-th of the continuous
// rate (so births are evenly spaced across steps and a fast node leaves an even trail, not
// clumps), the burst's time for bursts. They spawn where the node is at tb (the two matrices interpolated linearly) and
// are then advanced by the same update with h = t0 + dt − tb.
//
// Does not: parse JSON (emitter_desc.h), know about scenes or the ECS (emitter_scene.h, the adapter).
#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

#include <glm/glm.hpp>

#include "nimbus/media/emitter_desc.h"
#include "nimbus/media/particle_set.h"

namespace nimbus::media {

// The live particles of one emitter (index i across every array).
struct EmitterParticles {
    std::vector<glm::dvec3> position;  // world, m
    std::vector<glm::dvec3> velocity;  // world, m/s: the particle's own (initial push, buoyancy), without wind
    std::vector<double> age;           // s
    std::vector<double> lifetime;      // s
    std::vector<float> sizeScale;      // radius multiplier: (1 ± radius_jitter) × the node's uniform scale at birth

    std::size_t size() const { return position.size(); }
};

class EmitterSimulation {
public:
    // `nodeIndex` is mixed into the seed so two emitters with the same seed differ.
    explicit EmitterSimulation(EmitterDesc desc, int nodeIndex = 0);

    // Advances [t0, t0 + dt]. worldAtT0/worldAtT1: the emitter node's local-to-world matrix at both
    // ends. Hosts start at t0 = 0 and call with t0 = k·dt for k = 0, 1, 2, ...
    // Throws std::invalid_argument for dt <= 0 or a non-finite t0/dt.
    void step(double t0, double dt, const glm::dmat4& worldAtT0, const glm::dmat4& worldAtT1);

    // Appends the live particles as the renderers see them: radius = radius(a) × sizeScale,
    // sigma = medium.extinction × density(a), albedo/emission from the over-life curves (or the
    // medium's), g and phase from the medium; a = age / lifetime. Particles with sigma 0 are left out.
    void appendParticles(ParticleSet& out, const Medium& medium) const;

    const EmitterDesc& desc() const { return desc_; }
    const EmitterParticles& particles() const { return p_; }
    std::size_t size() const { return p_.size(); }
    std::size_t capacity() const { return desc_.maxParticles; }
    std::uint64_t spawnedCount() const { return spawned_; }
    std::uint64_t droppedCount() const { return dropped_; }

    // The turbulence velocity field (m/s, world) at `x` and time `t`: the curl of three Perlin
    // potentials, so it is divergence-free up to the finite-difference error, scaled so that its
    // RMS speed is turbulence.strength. Zero when off.
    glm::dvec3 turbulenceAt(const glm::dvec3& x, double t) const;

private:
    double uniform();  // [0, 1) from 53 random bits: portable, unlike std::uniform_real_distribution
    void spawn(double birth, double t0, double dt, const glm::dmat4& m0, const glm::dmat4& m1);
    void advance(std::size_t i, double h, double t);

    EmitterDesc desc_;
    std::mt19937_64 rng_;
    glm::dvec3 noiseOffset_[3]{};  // decorrelates the three potentials (and emitters)
    std::uint64_t nextBirth_ = 0;  // index of the next birth of the continuous rate
    std::vector<char> burstFired_;
    EmitterParticles p_;
    std::uint64_t spawned_ = 0;
    std::uint64_t dropped_ = 0;
};

}  // namespace nimbus::media
