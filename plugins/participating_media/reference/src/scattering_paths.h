#pragma once
// What the multiple-scattering model adds to the exact single-scattering quadrature (docs/design.md §2,
// `"scattering": "multiple"`), as an unbiased Monte Carlo estimate along one camera ray:
//   - light of every punctual light scattered two or more times,
//   - the environment (ambient radiance arriving from every direction where no mesh is in the
//     way), attenuated by the medium and scattered one or more times,
//   - emission scattered one or more times.
// A path starts at a collision on the camera ray and walks the medium:
//   - each flight's collision is sampled by inverting the closed-form optical depth (conditioned
//     on colliding before the flight leaves the medium or meets a mesh, with weight 1 − T);
//   - at each vertex one particle (or volume) of the mixture is chosen by its share of σ_t, its
//     albedo weights the path and its phase function gives the next direction;
//   - next-event estimation to every light with the exact closed-form transmittance and mesh
//     visibility from the second vertex on (the first is the quadrature's), and to the
//     environment along each sampled direction with that flight's exact transmittance;
//   - Russian roulette once a path's weight is below kRouletteWeight (survival ∝ its weight), and
//     from vertex kRouletteCap on at most 0.99, so a path at albedo 1 ends too; both without bias.
// Mesh-reflected light is left out: a flight that meets a mesh ends there (docs/design.md §2).
//
// Does not: add the camera ray's own single scattering or emission (the quadrature does), or fog
// (the caller fogs at the first collision's distance).
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "light_transport.h"
#include "nimbus/media/particle_bvh.h"
#include "nimbus/media/particle_set.h"
#include "nimbus/media/volume.h"
#include "nimbus/raycast/mesh_raycaster.h"
#include "view_ray_medium.h"

namespace nimbus::media::reference {

// A counter-based generator (SplitMix64): each pixel's samples come from its own stream, so an
// image has the same bits for any thread count.
class PathRandom {
public:
    PathRandom(std::uint64_t seed, std::uint64_t stream);
    double uniform();  // [0, 1)

private:
    std::uint64_t state_;
};

// A path's answer: the radiance it brings to the camera ray, its collision's distance along it
// (for fog), and how many vertices it had.
struct PathSample {
    glm::dvec3 radiance{0.0};
    double firstDistance = 0.0;
    int vertices = 0;
};

class ScatteringPaths {
public:
    ScatteringPaths(const LightTransport& light, const raycast::MeshRaycaster& meshes, const ParticleBvh& bvh,
                    const ParticleSet& particles, const glm::dvec3& environment);

    // One path from the camera ray origin + t·dir, whose medium `camera` is built (empty: none).
    // `flight` is scratch reused between calls.
    PathSample sample(const glm::dvec3& origin, const glm::dvec3& dir, const ViewRayMedium& camera, PathRandom& random,
                      ViewRayMedium& flight, std::vector<double>& weights) const;

    // Where survival is capped at 0.99: most paths of a dense cloud end before (diffusion across
    // τ takes about τ² vertices), and weights grow past 1 only beyond it.
    static constexpr int kRouletteCap = 256;
    static constexpr double kRouletteWeight = 0.05;
    // The most vertices a path may have: a bound no path of survival ≤ 0.99 reaches (0.99^10⁵).
    static constexpr int kMaxVertices = 100000;

private:
    struct Vertex {
        glm::dvec3 position{0.0};
        glm::dvec3 arriving{0.0};  // the direction the path travelled to it
        glm::dvec3 albedo{0.0};
        glm::dvec3 emission{0.0};
        PhaseFunction phase = PhaseFunction::HenyeyGreenstein;
        double g = 0.0;
    };
    // A collision on `medium` (not empty) drawn ∝ σ_t T, and the mixture member it met.
    bool collide(const ViewRayMedium& medium, const glm::dvec3& origin, const glm::dvec3& dir, PathRandom& random,
                 std::vector<double>& weights, Vertex& out, double& distance) const;

    const LightTransport& light_;
    const raycast::MeshRaycaster& meshes_;
    const ParticleBvh& bvh_;
    const ParticleSet& particles_;
    glm::dvec3 environment_;
};

// The direction light came from at a vertex reached along `arriving`: drawn from the phase
// function (HG with asymmetry g, or Rayleigh) about it. cos θ = dot(result, arriving).
glm::dvec3 samplePhaseDirection(PhaseFunction phase, double g, const glm::dvec3& arriving, double u1, double u2);

// cos θ of Henyey–Greenstein by inversion of its CDF (|g| < 1e-4: isotropic).
double sampleHenyeyGreensteinCosine(double g, double u);
// cos θ of the Rayleigh phase (3/(16π))(1 + cos²θ) by Cardano on its cubic CDF.
double sampleRayleighCosine(double u);

}  // namespace nimbus::media::reference
