#pragma once
// Light arriving at points of the scene (docs/design.md §2): per light, the irradiance E_l
// (assets::sampleLight) × mesh visibility V_l (Embree) × medium transmittance T_l (closed form over the
// particles the BVH finds and the volumes). Used for the in-scattering source at medium points and
// for mesh shading. `sourceAmbient` is what every medium point scatters unshadowed: the ambient in
// the single-scattering model, 0 in the multiple one (where the environment is a light the paths
// of scattering_paths.h sample).
//
// Does not: integrate along view rays (reference_renderer.cpp does), or cache anything between calls.
#include <vector>

#include <glm/glm.hpp>

#include "nimbus/assets/material_sampling.h"
#include "nimbus/assets/scene_queries.h"
#include "nimbus/media/particle_bvh.h"
#include "nimbus/media/particle_set.h"
#include "nimbus/raycast/mesh_raycaster.h"
#include "view_ray_medium.h"

namespace nimbus::media::reference {

// Optical depth beyond which light is treated as fully absorbed: exp(-64) < 2e-28.
inline constexpr double kOpaqueDepth = 64.0;

class LightTransport {
public:
    LightTransport(const std::vector<assets::ResolvedLight>& lights, const raycast::MeshRaycaster& meshes, const ParticleBvh& bvh,
                   const ParticleSet& particles, const std::vector<Volume>& volumes, const glm::dvec3& sourceAmbient,
                   const glm::dvec3& surfaceAmbient);

    // T_l: exp(-τ) through every particle and volume on the segment x + s·toLight, s in [0, distance].
    double transmittanceToLight(const glm::dvec3& x, const glm::dvec3& toLight, double distance) const;
    // The optical depth itself, stopping early once it is past kOpaqueDepth.
    double opticalDepthToLight(const glm::dvec3& x, const glm::dvec3& toLight, double distance) const;

    // Σ_l p(θ_l) E_l V_l T_l at x for light arriving towards `dir` (x seen along dir), with one
    // phase function: what a path vertex sends on (scattering_paths.cpp).
    glm::dvec3 directLight(const glm::dvec3& x, const glm::dvec3& dir, PhaseFunction phase, double g) const;

    // A ray particle's optical properties (a particle's or a volume's).
    const glm::vec3& albedo(const RayParticle& p) const { return p.volume ? volumes_[p.index].medium.albedo : particles_.albedo[p.index]; }
    const glm::vec3& emission(const RayParticle& p) const { return p.volume ? volumes_[p.index].medium.emission : particles_.emission[p.index]; }
    float g(const RayParticle& p) const { return p.volume ? volumes_[p.index].medium.g : particles_.g[p.index]; }
    PhaseFunction phase(const RayParticle& p) const { return p.volume ? volumes_[p.index].medium.phase : particles_.phase[p.index]; }
    const std::vector<Volume>& volumes() const { return volumes_; }

    // The σ-weighted source S̄ at ray parameter t of a view ray (x = origin + t·dir), from the active
    // particles of `piece`:
    //   S̄ = Σ_i w_i [a_i (Σ_l p_i(θ_l) E_l V_l T_l + L_amb) + e_i] / Σ_i w_i,   w_i = σ_i ρ_i(x).
    glm::dvec3 mediumSource(const glm::dvec3& origin, const glm::dvec3& dir, const ViewRayMedium& medium,
                            std::uint32_t piece, double t, std::vector<double>& weights) const;

    // L_s = Σ_l f(l, v) E_l max(0, n·l) V_l T_l + baseColor L_amb + emissive at a mesh hit seen along
    // dir (v = −dir), f the glTF BRDF of assets/surface_brdf.h.
    glm::dvec3 surfaceRadiance(const raycast::MeshHit& hit, const glm::dvec3& dir, bool doubleSided,
                               const assets::MaterialSample& material) const;

private:
    const std::vector<assets::ResolvedLight>& lights_;
    const raycast::MeshRaycaster& meshes_;
    const ParticleBvh& bvh_;
    const ParticleSet& particles_;
    const std::vector<Volume>& volumes_;
    glm::dvec3 sourceAmbient_, surfaceAmbient_;
};

}  // namespace nimbus::media::reference
