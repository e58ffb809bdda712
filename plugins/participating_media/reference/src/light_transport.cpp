#include "light_transport.h"

#include <cmath>

#include "nimbus/assets/light_model.h"
#include "nimbus/assets/surface_brdf.h"
#include "nimbus/media/optics.h"

namespace nimbus::media::reference {

LightTransport::LightTransport(const std::vector<assets::ResolvedLight>& lights, const raycast::MeshRaycaster& meshes, const ParticleBvh& bvh,
                               const ParticleSet& particles, const std::vector<Volume>& volumes, const glm::dvec3& sourceAmbient,
                               const glm::dvec3& surfaceAmbient)
    : lights_(lights), meshes_(meshes), bvh_(bvh), particles_(particles), volumes_(volumes), sourceAmbient_(sourceAmbient),
      surfaceAmbient_(surfaceAmbient) {}

double LightTransport::opticalDepthToLight(const glm::dvec3& x, const glm::dvec3& toLight, double distance) const {
    double tau = 0.0;
    for (const Volume& v : volumes_) tau += volumeOpticalDepth(v, x, toLight, 0.0, distance);
    if (tau >= kOpaqueDepth) return tau;
    bvh_.forEachOnSegment(x, toLight, 0.0, distance, [&](std::uint32_t i) {
        const double radius = particles_.radius[i];
        const ChordGeometry chord = chordGeometry(x, toLight, particles_.position[i], radius);
        tau += particleOpticalDepth(chord, particles_.sigma[i], radius, 0.0, distance);
        return tau < kOpaqueDepth;
    });
    return tau;
}

double LightTransport::transmittanceToLight(const glm::dvec3& x, const glm::dvec3& toLight, double distance) const {
    const double tau = opticalDepthToLight(x, toLight, distance);
    return tau < kOpaqueDepth ? transmittance(tau) : 0.0;
}

glm::dvec3 LightTransport::directLight(const glm::dvec3& x, const glm::dvec3& dir, PhaseFunction phase, double g) const {
    glm::dvec3 sum(0.0);
    for (const assets::ResolvedLight& light : lights_) {
        const assets::LightSample sample = assets::sampleLight(light, x);
        if (sample.irradiance == glm::dvec3(0.0)) continue;
        const double p = phaseValue(phase, g, glm::dot(sample.toLight, dir));
        if (!(p > 0.0) || meshes_.occluded(x, sample.toLight, sample.distance)) continue;
        const double T = transmittanceToLight(x, sample.toLight, sample.distance);
        if (T > 0.0) sum += sample.irradiance * (p * T);
    }
    return sum;
}

glm::dvec3 LightTransport::mediumSource(const glm::dvec3& origin, const glm::dvec3& dir, const ViewRayMedium& medium,
                                        std::uint32_t piece, double t, std::vector<double>& weights) const {
    const double sigmaT = medium.extinctionAt(piece, t, &weights);
    if (!(sigmaT > 0.0)) return glm::dvec3(0.0);
    const std::vector<RayParticle>& rayParticles = medium.particles();
    const std::uint32_t* active = medium.activeBegin(piece);
    const std::size_t count = weights.size();

    glm::dvec3 scatter(0.0), emission(0.0);
    for (std::size_t j = 0; j < count; ++j) {
        const RayParticle& rp = rayParticles[active[j]];
        scatter += weights[j] * glm::dvec3(albedo(rp));
        emission += weights[j] * glm::dvec3(this->emission(rp));
    }
    glm::dvec3 source = sourceAmbient_ * scatter + emission;
    if (scatter == glm::dvec3(0.0)) return source / sigmaT;  // albedo 0: lights cannot contribute

    const glm::dvec3 x = origin + t * dir;
    for (const assets::ResolvedLight& light : lights_) {
        const assets::LightSample sample = assets::sampleLight(light, x);
        if (sample.irradiance == glm::dvec3(0.0)) continue;
        // cosθ between the light's travel direction (-toLight) and the way to the camera (-dir).
        const double cosTheta = glm::dot(sample.toLight, dir);
        glm::dvec3 phased(0.0);
        float lastG = 2.0f;  // particles of one medium share g: evaluate the phase once per run
        PhaseFunction lastPhase = PhaseFunction::HenyeyGreenstein;
        double p = 0.0;
        for (std::size_t j = 0; j < count; ++j) {
            const RayParticle& rp = rayParticles[active[j]];
            if (g(rp) != lastG || phase(rp) != lastPhase) {
                lastG = g(rp);
                lastPhase = phase(rp);
                p = phaseValue(lastPhase, lastG, cosTheta);
            }
            phased += (weights[j] * p) * glm::dvec3(albedo(rp));
        }
        if (phased == glm::dvec3(0.0)) continue;
        if (meshes_.occluded(x, sample.toLight, sample.distance)) continue;
        const double T = transmittanceToLight(x, sample.toLight, sample.distance);
        if (T > 0.0) source += sample.irradiance * (T * phased);
    }
    return source / sigmaT;
}

glm::dvec3 LightTransport::surfaceRadiance(const raycast::MeshHit& hit, const glm::dvec3& dir, bool doubleSided,
                                           const assets::MaterialSample& material) const {
    glm::dvec3 n = hit.shadingNormal;
    if (doubleSided && glm::dot(n, dir) > 0.0) n = -n;  // face the viewer
    const glm::dvec3 base(material.baseColor);
    const assets::SurfaceBrdf brdf = assets::surfaceBrdf(base, material.metallic, material.roughness);
    glm::dvec3 direct(0.0);
    for (const assets::ResolvedLight& light : lights_) {
        const assets::LightSample sample = assets::sampleLight(light, hit.position);
        const double cosine = glm::dot(n, sample.toLight);
        if (!(cosine > 0.0) || sample.irradiance == glm::dvec3(0.0)) continue;
        if (meshes_.occludedFromSurface(hit, sample.toLight, sample.distance)) continue;
        const double T = transmittanceToLight(hit.position, sample.toLight, sample.distance);
        direct += sample.irradiance * T * assets::brdfTimesCosine(brdf, n, -dir, sample.toLight, cosine);
    }
    return direct + base * surfaceAmbient_ + material.emissive;
}

}  // namespace nimbus::media::reference
