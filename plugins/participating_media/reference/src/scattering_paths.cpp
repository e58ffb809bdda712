#include "scattering_paths.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/gtx/component_wise.hpp>

#include "nimbus/media/optics.h"

namespace nimbus::media::reference {
namespace {

std::uint64_t splitMix(std::uint64_t& state) {
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

// An orthonormal basis around unit n (Duff et al., "Building an Orthonormal Basis, Revisited").
void basisAround(const glm::dvec3& n, glm::dvec3& t, glm::dvec3& b) {
    const double sign = std::copysign(1.0, n.z);
    const double a = -1.0 / (sign + n.z);
    const double c = n.x * n.y * a;
    t = glm::dvec3(1.0 + sign * n.x * n.x * a, sign * c, -sign * n.x);
    b = glm::dvec3(c, sign + n.y * n.y * a, -n.y);
}

// Σ optical depth of every cluster: the sum the collision is drawn against.
double mediumDepth(const ViewRayMedium& medium) {
    if (medium.empty()) return 0.0;
    const RayCluster& last = medium.clusters().back();
    return last.opticalDepthBefore + last.opticalDepth;
}

}  // namespace

PathRandom::PathRandom(std::uint64_t seed, std::uint64_t stream) : state_(seed * 0xD1B54A32D192ED03ull + stream) {
    (void)splitMix(state_);
}

double PathRandom::uniform() { return static_cast<double>(splitMix(state_) >> 11) * 0x1.0p-53; }

double sampleHenyeyGreensteinCosine(double g, double u) {
    if (std::abs(g) < 1e-4) return 1.0 - 2.0 * u;
    const double s = (1.0 - g * g) / (1.0 - g + 2.0 * g * u);
    return std::clamp((1.0 + g * g - s * s) / (2.0 * g), -1.0, 1.0);
}

double sampleRayleighCosine(double u) {
    // CDF (3μ + μ³ + 4)/8 = u: μ³ + 3μ − 4(2u − 1) = 0, one real root.
    const double q = 2.0 * (2.0 * u - 1.0);
    const double r = std::sqrt(q * q + 1.0);
    return std::clamp(std::cbrt(q + r) + std::cbrt(q - r), -1.0, 1.0);
}

glm::dvec3 samplePhaseDirection(PhaseFunction phase, double g, const glm::dvec3& arriving, double u1, double u2) {
    const double cosine = phase == PhaseFunction::Rayleigh ? sampleRayleighCosine(u1) : sampleHenyeyGreensteinCosine(g, u1);
    const double sine = std::sqrt(std::max(0.0, 1.0 - cosine * cosine));
    const double phi = 2.0 * kPi * u2;
    glm::dvec3 t, b;
    basisAround(arriving, t, b);
    return glm::normalize(cosine * arriving + sine * (std::cos(phi) * t + std::sin(phi) * b));
}

ScatteringPaths::ScatteringPaths(const LightTransport& light, const raycast::MeshRaycaster& meshes, const ParticleBvh& bvh,
                                 const ParticleSet& particles, const glm::dvec3& environment)
    : light_(light), meshes_(meshes), bvh_(bvh), particles_(particles), environment_(environment) {}

bool ScatteringPaths::collide(const ViewRayMedium& medium, const glm::dvec3& origin, const glm::dvec3& dir, PathRandom& random,
                              std::vector<double>& weights, Vertex& out, double& distance) const {
    const double total = mediumDepth(medium);
    // τ* on [0, τ] with density e^−τ* / (1 − e^−τ): the collision given that there is one.
    const double target = -std::log1p(-random.uniform() * opacity(total));
    const auto& clusters = medium.clusters();
    std::uint32_t c = 0;
    while (c + 1 < clusters.size() && target >= clusters[c].opticalDepthBefore + clusters[c].opticalDepth) ++c;
    const RaySample s = medium.locate(c, target - clusters[c].opticalDepthBefore);
    const double sigma = medium.extinctionAt(s.piece, s.t, &weights);
    if (!(sigma > 0.0)) return false;
    // The mixture member by its share of σ_t.
    const double pick = random.uniform() * sigma;
    const std::uint32_t* active = medium.activeBegin(s.piece);
    std::size_t j = 0;
    for (double sum = weights[0]; j + 1 < weights.size() && sum <= pick; sum += weights[++j]) {}
    const RayParticle& member = medium.particles()[active[j]];
    out.position = origin + s.t * dir;
    out.arriving = dir;
    out.albedo = glm::dvec3(light_.albedo(member));
    out.emission = glm::dvec3(light_.emission(member));
    out.phase = light_.phase(member);
    out.g = light_.g(member);
    distance = s.t;
    return true;
}

PathSample ScatteringPaths::sample(const glm::dvec3& origin, const glm::dvec3& dir, const ViewRayMedium& camera, PathRandom& random,
                                   ViewRayMedium& flight, std::vector<double>& weights) const {
    PathSample out;
    if (camera.empty()) return out;
    Vertex v;
    if (!collide(camera, origin, dir, random, weights, v, out.firstDistance)) return out;
    glm::dvec3 weight(opacity(mediumDepth(camera)));  // the camera ray's chance to collide at all
    for (int vertex = 1; vertex <= kMaxVertices; ++vertex) {
        out.vertices = vertex;
        weight *= v.albedo;
        if (vertex >= 2) out.radiance += weight * light_.directLight(v.position, v.arriving, v.phase, v.g);
        if (!(glm::compMax(weight) > 0.0)) break;
        const double u1 = random.uniform(), u2 = random.uniform();
        const glm::dvec3 next = samplePhaseDirection(v.phase, v.g, v.arriving, u1, u2);
        const auto hit = meshes_.closestHit(v.position, next, 0.0, std::numeric_limits<double>::infinity(), raycast::FaceCulling::None);
        const double end = hit ? hit->distance : std::numeric_limits<double>::infinity();
        flight.build(bvh_, particles_, v.position, next, end, light_.volumes());
        const double tau = mediumDepth(flight);
        // Where the flight escapes, the environment arrives through the medium it crossed.
        if (!hit) out.radiance += weight * environment_ * transmittance(tau);
        if (flight.empty() || !(tau > 0.0)) break;
        weight *= opacity(tau);
        const glm::dvec3 from = v.position;
        double t = 0.0;
        if (!collide(flight, from, next, random, weights, v, t)) break;
        out.radiance += weight * v.emission;  // emission at the new vertex, scattered `vertex` times
        // Roulette only below kRouletteWeight, raising survivors to it: a path that merely left a
        // thin medium keeps its weight, and no weight exceeds 1. Past kRouletteCap vertices a path
        // at albedo 1 survives each vertex with 0.99 at most, so it ends too.
        const double survive = std::min(vertex < kRouletteCap ? 1.0 : 0.99, glm::compMax(weight) / kRouletteWeight);
        if (survive < 1.0) {
            if (!(random.uniform() < survive)) break;
            weight /= survive;
        }
    }
    return out;
}

}  // namespace nimbus::media::reference
