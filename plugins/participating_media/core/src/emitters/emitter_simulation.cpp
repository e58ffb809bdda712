#include "nimbus/media/emitter_simulation.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <utility>

#include <glm/gtc/noise.hpp>

namespace nimbus::media {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr double kNoiseStep = 0.01;  // central-difference step, in swirl sizes
// RMS speed of the raw curl of the three potentials (measured over 2·10⁵ random points):
// dividing by it makes `strength` the RMS speed of the turbulence.
constexpr double kCurlRms = 1.91;
// Each potential drifts through the noise along its own direction as time passes, so the curl of
// the three evolves (a single drift direction would only translate the pattern).
constexpr glm::dvec3 kDrift[3] = {{0.57735026918962573, 0.57735026918962573, 0.57735026918962573},
                                  {-0.80178372573727319, 0.26726124191242440, 0.53452248382484879},
                                  {0.0, -0.89442719099991586, 0.44721359549995793}};

// SplitMix64's finaliser: spreads seed and node index over all 64 bits before seeding the engine.
std::uint64_t mix(std::uint64_t x) {
    x += 0x9e3779b97f4a7c15ull;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
    return x ^ (x >> 31);
}

// An orthonormal basis around unit `n` without a branch on a threshold (Duff et al. 2017).
void basis(const glm::dvec3& n, glm::dvec3& b1, glm::dvec3& b2) {
    const double sign = std::copysign(1.0, n.z);
    const double a = -1.0 / (sign + n.z);
    const double b = n.x * n.y * a;
    b1 = {1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x};
    b2 = {b, sign + n.y * n.y * a, -n.y};
}

double uniformScale(const glm::dmat4& m) { return std::cbrt(std::abs(glm::determinant(glm::dmat3(m)))); }

template <class T>
void moveLastInto(std::vector<T>& v, std::size_t i) {
    v[i] = v.back();
    v.pop_back();
}

}  // namespace

EmitterSimulation::EmitterSimulation(EmitterDesc desc, int nodeIndex) : desc_(std::move(desc)) {
    rng_.seed(mix(static_cast<std::uint64_t>(desc_.seed) ^ mix(static_cast<std::uint64_t>(static_cast<std::int64_t>(nodeIndex)))));
    // Drawn z, y, x in sequence: the order GCC happened to evaluate these constructor arguments in
    // (unspecified in C++), now fixed so every compiler simulates the same particles.
    for (glm::dvec3& o : noiseOffset_) {
        const double z = uniform(), y = uniform(), x = uniform();
        o = glm::dvec3(x, y, z) * 256.0;
    }
    burstFired_.assign(desc_.bursts.size(), 0);
    const std::size_t n = desc_.maxParticles;
    p_.position.reserve(n);
    p_.velocity.reserve(n);
    p_.age.reserve(n);
    p_.lifetime.reserve(n);
    p_.sizeScale.reserve(n);
}

double EmitterSimulation::uniform() { return static_cast<double>(rng_() >> 11) * 0x1.0p-53; }

glm::dvec3 EmitterSimulation::turbulenceAt(const glm::dvec3& x, double t) const {
    const EmitterTurbulence& turb = desc_.turbulence;
    if (!(turb.strength > 0.0)) return glm::dvec3(0.0);
    // GLM's classic Perlin noise, in double: smooth (C²) and precise at any distance from the
    // origin. GLM's simplex noise is not continuous (its kernels overlap neighbouring simplices),
    // which finite differences turn into velocity spikes.
    const glm::dvec3 q = x / turb.scale;
    const double tau = t * turb.speed / turb.scale;
    // ∂ψ_k/∂q_a by central differences; only the six the curl needs are evaluated.
    const auto derivative = [&](int k, int a) {
        glm::dvec3 d(0.0);
        d[a] = kNoiseStep;
        const glm::dvec3 c = q + noiseOffset_[k] + tau * kDrift[k];
        return (glm::perlin(c + d) - glm::perlin(c - d)) / (2.0 * kNoiseStep);
    };
    const glm::dvec3 curl(derivative(2, 1) - derivative(1, 2), derivative(0, 2) - derivative(2, 0),
                          derivative(1, 0) - derivative(0, 1));
    return (turb.strength / kCurlRms) * curl;
}

void EmitterSimulation::advance(std::size_t i, double h, double t) {
    glm::dvec3 v = p_.velocity[i];
    v.y += desc_.buoyancy * h;
    v /= 1.0 + desc_.drag * h;
    p_.velocity[i] = v;
    p_.position[i] += h * (v + desc_.wind + turbulenceAt(p_.position[i], t));
    p_.age[i] += h;
}

void EmitterSimulation::spawn(double birth, double t0, double dt, const glm::dmat4& m0, const glm::dmat4& m1) {
    if (p_.size() >= desc_.maxParticles) {
        ++dropped_;
        return;
    }
    ++spawned_;
    // Always eight draws per spawn, whatever the shape: the stream stays aligned across settings.
    double u[8];
    for (double& x : u) x = uniform();

    glm::dvec3 local(0.0);
    switch (desc_.shape) {
        case SpawnShape::Point: break;
        case SpawnShape::Sphere: {
            const double r = desc_.shapeRadius * std::cbrt(u[0]);
            const double z = 1.0 - 2.0 * u[1];
            const double s = std::sqrt(std::max(0.0, 1.0 - z * z));
            local = r * glm::dvec3(s * std::cos(kTwoPi * u[2]), s * std::sin(kTwoPi * u[2]), z);
            break;
        }
        case SpawnShape::Box: local = (glm::dvec3(u[0], u[1], u[2]) - 0.5) * desc_.shapeSize; break;
        case SpawnShape::Disc: {
            const double r = desc_.shapeRadius * std::sqrt(u[0]);
            local = {r * std::cos(kTwoPi * u[1]), 0.0, r * std::sin(kTwoPi * u[1])};
            break;
        }
    }

    glm::dvec3 localVelocity(0.0);
    const double speed = glm::length(desc_.velocity);
    if (speed > 0.0) {
        const glm::dvec3 axis = desc_.velocity / speed;
        glm::dvec3 b1, b2;
        basis(axis, b1, b2);
        const double cosTheta = 1.0 - u[3] * (1.0 - std::cos(desc_.spread));
        const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
        const double phi = kTwoPi * u[4];
        const glm::dvec3 dir = b1 * (sinTheta * std::cos(phi)) + b2 * (sinTheta * std::sin(phi)) + axis * cosTheta;
        localVelocity = dir * (speed * (1.0 + desc_.speedJitter * (2.0 * u[5] - 1.0)));
    }

    // Where the node is at the birth time: the two ends of the step, interpolated linearly.
    const double f = std::clamp((birth - t0) / dt, 0.0, 1.0);
    const glm::dvec3 p0 = glm::dvec3(m0 * glm::dvec4(local, 1.0)), p1 = glm::dvec3(m1 * glm::dvec4(local, 1.0));
    const glm::dvec3 v0 = glm::dmat3(m0) * localVelocity, v1 = glm::dmat3(m1) * localVelocity;
    const glm::dvec3 nodeVelocity = (glm::dvec3(m1[3]) - glm::dvec3(m0[3])) / dt;
    const double s0 = uniformScale(m0);
    const double scale = s0 + (uniformScale(m1) - s0) * f;

    const double lifetime = desc_.lifetimeMin + (desc_.lifetimeMax - desc_.lifetimeMin) * u[6];
    const double remaining = (t0 + dt) - birth;
    if (remaining >= lifetime) return;  // born and dead within this step

    // a + (b − a)·f rather than a(1 − f) + b·f: exact when the node does not move.
    p_.position.push_back(p0 + (p1 - p0) * f);
    p_.velocity.push_back(v0 + (v1 - v0) * f + desc_.inheritVelocity * nodeVelocity);
    p_.age.push_back(0.0);
    p_.lifetime.push_back(lifetime);
    p_.sizeScale.push_back(static_cast<float>((1.0 + desc_.radiusJitter * (2.0 * u[7] - 1.0)) * scale));
    advance(p_.size() - 1, remaining, birth);
}

void EmitterSimulation::step(double t0, double dt, const glm::dmat4& worldAtT0, const glm::dmat4& worldAtT1) {
    if (!(dt > 0.0) || !std::isfinite(dt) || !std::isfinite(t0))
        throw std::invalid_argument("EmitterSimulation::step: dt must be > 0 and t0, dt finite");
    const double t1 = t0 + dt;

    // Age and move the living; the dead are replaced by the last particle, which is then examined.
    for (std::size_t i = 0; i < p_.size();) {
        if (p_.age[i] + dt >= p_.lifetime[i]) {
            moveLastInto(p_.position, i);
            moveLastInto(p_.velocity, i);
            moveLastInto(p_.age, i);
            moveLastInto(p_.lifetime, i);
            moveLastInto(p_.sizeScale, i);
            continue;
        }
        advance(i, dt, t0);
        ++i;
    }

    // Bursts: each fires once, in the first step that reaches its time.
    for (std::size_t b = 0; b < desc_.bursts.size(); ++b) {
        if (burstFired_[b] || !(desc_.bursts[b].time < t1)) continue;
        burstFired_[b] = 1;
        const double birth = std::max(desc_.bursts[b].time, t0);
        for (std::uint32_t k = 0; k < desc_.bursts[b].count; ++k) spawn(birth, t0, dt, worldAtT0, worldAtT1);
    }

    // Continuous rate: the m-th particle (m = 0, 1, 2, ...) is born at start + m / rate, computed
    // from m rather than accumulated, so births are exactly 1/rate apart across step boundaries
    // and none is lost or doubled when consecutive steps' ends differ by an ulp.
    if (desc_.rate > 0.0) {
        const double end = std::min(t1, desc_.stop);
        // A host that starts late does not replay the backlog (births older than one step).
        const double overdue = std::ceil((t0 - dt - desc_.start) * desc_.rate);
        if (overdue > static_cast<double>(nextBirth_)) nextBirth_ = static_cast<std::uint64_t>(overdue);
        for (;;) {
            const double birth = desc_.start + static_cast<double>(nextBirth_) / desc_.rate;
            if (!(birth < end)) break;
            spawn(std::max(birth, t0), t0, dt, worldAtT0, worldAtT1);
            ++nextBirth_;
        }
    }
}

void EmitterSimulation::appendParticles(ParticleSet& out, const Medium& medium) const {
    Medium m = medium;
    for (std::size_t i = 0; i < p_.size(); ++i) {
        const float a = static_cast<float>(std::clamp(p_.age[i] / p_.lifetime[i], 0.0, 1.0));
        const float sigma = medium.extinction * desc_.density.at(a);
        if (!(sigma > 0.0f)) continue;
        const float radius = desc_.radius.at(a) * p_.sizeScale[i];
        if (!desc_.albedoOverLife.empty()) m.albedo = desc_.albedoOverLife.at(a);
        if (!desc_.emissionOverLife.empty()) m.emission = desc_.emissionOverLife.at(a);
        out.push(p_.position[i], radius, sigma, m);
    }
}

}  // namespace nimbus::media
