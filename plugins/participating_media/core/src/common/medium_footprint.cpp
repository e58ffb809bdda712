// The particles' footprint for the frame's planning (nimbus/media/medium_footprint.h).
#include "nimbus/media/medium_footprint.h"

#include <algorithm>
#include <cmath>

namespace nimbus::media {

Aabb particleBounds(const ParticleSet& particles) {
    Aabb bounds;
    for (std::size_t i = 0; i < particles.size(); ++i) {
        const glm::dvec3 r(particles.radius[i]);
        bounds.extend(particles.position[i] - r);
        bounds.extend(particles.position[i] + r);
    }
    return bounds;
}

SplatFootprint splatFootprint(const ParticleSet& particles, const gpu::View& view) {
    const double pixels = static_cast<double>(view.width) * view.height;
    const glm::dmat4 viewMatrix(view.view);
    // Pixels per metre at depth 1 (perspective) or per metre (orthographic), vertically.
    const double scale = view.height / (2.0 * (view.orthographic ? view.orthoHalfExtent.y : view.tanHalfFovY));
    double covered = 0.0, radiusTimesArea = 0.0;
    for (std::size_t i = 0; i < particles.size(); ++i) {
        const glm::dvec3 c(viewMatrix * glm::dvec4(particles.position[i] - view.origin, 1.0));
        const double r = particles.radius[i], depth = -c.z;
        if (!view.orthographic && depth <= r) {
            covered += pixels;  // in front of or around the eye: a full-screen quad
            radiusTimesArea += pixels * std::sqrt(pixels);
            continue;
        }
        const double half = r * scale / (view.orthographic ? 1.0 : depth);  // the quad's half size in pixels
        const double area = std::min(4.0 * half * half, pixels);
        covered += area;
        radiusTimesArea += area * half;
    }
    return {covered / pixels, covered > 0.0 ? radiusTimesArea / covered : 0.0};
}

float automaticMediaScale(const SplatFootprint& footprint, bool lampAmongParticles) {
    // A lamp among the particles lights a peak a few pixels wide, which a lower resolution blurs away.
    if (footprint.coverage <= kHalfScaleCoverage || lampAmongParticles) return 1.0f;
    return static_cast<float>(std::clamp(kAutoScaleRadiusTexels / footprint.radiusPixels, 0.25, 0.5));
}

bool lampAmongParticles(const std::vector<Light>& lights, const Aabb& bounds) {
    return std::any_of(lights.begin(), lights.end(), [&](const Light& l) {
        return l.kind != gpu::LightKind::Directional && bounds.contains(l.position);
    });
}

bool lampInsideMedium(const ParticleSet& particles, const std::vector<Light>& lights) {
    // Peak column through a particle's centre: σ ∫ e^{−k u²} du over the chord ≈ 0.8355·σR.
    constexpr double kColumnPerSigmaRadius = 0.8355;
    for (const auto& light : lights) {
        if (light.kind == gpu::LightKind::Directional) continue;
        for (std::size_t i = 0; i < particles.size(); ++i) {
            const double r = particles.radius[i];
            if (kColumnPerSigmaRadius * particles.sigma[i] * r > kLampMediumColumn && glm::length(light.position - particles.position[i]) < r)
                return true;
        }
    }
    return false;
}

std::vector<std::uint8_t> particlesNearMeshes(const std::vector<OccluderBox>& meshes, const ParticleSet& particles, double reach) {
    std::vector<std::uint8_t> near(particles.size(), 0);
    // Only meshes whose axis-aligned hull comes within reach of the particles' bounds are tested
    // particle by particle (a level of many meshes around one cloud).
    const Aabb bounds = particleBounds(particles);
    const double maxRadius = particles.empty() ? 0.0 : *std::max_element(particles.radius.begin(), particles.radius.end());
    const glm::dvec3 slack(std::max(reach - 1.0, 0.0) * maxRadius);
    for (const OccluderBox& box : meshes) {
        const glm::dvec3 hull = axisAlignedHalf(box);
        if (bounds.empty() || glm::any(glm::greaterThan(box.centre - hull, bounds.max + slack)) ||
            glm::any(glm::lessThan(box.centre + hull, bounds.min - slack)))
            continue;
        for (std::size_t i = 0; i < particles.size(); ++i) {
            const double r = reach * particles.radius[i];
            if (squaredDistance(box, particles.position[i]) < r * r) near[i] = 1;
        }
    }
    return near;
}

std::vector<std::uint8_t> particlesNearLamps(const ParticleSet& particles, const std::vector<Light>& lights, std::span<const int> lamps,
                                             double reach) {
    std::vector<std::uint8_t> near(particles.size(), 0);
    for (const int index : lamps) {
        if (index < 0) break;
        const Light& lamp = lights[static_cast<std::size_t>(index)];
        for (std::size_t i = 0; i < particles.size(); ++i) {
            const glm::dvec3 toParticle = particles.position[i] - lamp.position;
            const double d = glm::length(toParticle), r = particles.radius[i];
            bool isNear = d < reach * r;
            if (!isNear && lamp.kind == gpu::LightKind::Spot) {
                // The angle of its centre off the axis, ± the angle its sphere spans from the lamp.
                const double off = std::acos(std::clamp(glm::dot(toParticle / d, lamp.direction), -1.0, 1.0));
                const double spans = std::asin(std::min(r / d, 1.0));
                isNear = off + spans > lamp.innerConeAngle && off - spans < lamp.outerConeAngle;
            }
            if (isNear) near[i] = 1;
        }
    }
    return near;
}

bool eyeInsideMedium(const ParticleSet& particles, const gpu::View& view) {
    for (std::size_t i = 0; i < particles.size(); ++i) {
        const glm::dvec3 d = particles.position[i] - view.origin;
        // Orthographic rays start on the camera's plane: a particle crossing it holds their start.
        const double distance = view.orthographic ? std::abs(glm::dot(d, view.forward)) : glm::length(d);
        if (distance < particles.radius[i]) return true;
    }
    return false;
}

}  // namespace nimbus::media
