#include "common/voxel_light.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace nimbus::media {

Arrival arrival(const Light& light, const glm::dvec3& p) {
    Arrival a;
    if (light.kind == gpu::LightKind::Directional) {
        a.toLight = -light.direction;
        a.distance = std::numeric_limits<double>::infinity();
        a.irradiance = light.radiance;
        return a;
    }
    const glm::dvec3 d = light.position - p;
    a.distance = glm::length(d);
    if (!(a.distance > 1e-9)) return a;
    a.toLight = d / a.distance;
    double scale = 1.0 / (a.distance * a.distance);
    if (light.range > 0.0) scale *= std::pow(std::clamp(1.0 - std::pow(a.distance / light.range, 4.0), 0.0, 1.0), 2.0);
    if (light.kind == gpu::LightKind::Spot) {
        const double cosOuter = std::cos(light.outerConeAngle);
        const double k = 1.0 / std::max(0.001, std::cos(light.innerConeAngle) - cosOuter);
        const double c = std::clamp(glm::dot(-a.toLight, light.direction) * k - cosOuter * k, 0.0, 1.0);
        scale *= c * c;
    }
    a.irradiance = light.radiance * static_cast<float>(scale);
    return a;
}

// The light that arrives at the voxel of side h around p, relative to the centre's transmittance:
// the centre's irradiance times the mean across the voxel along the light (a dense voxel's lit face
// scatters most), e^{−τ_c} · 2 sinh(τ_v/2) / τ_v for optical depth τ_v across it. Where a point or
// spot light lies within two voxels, 1/r² and the depth to the light both change across the voxel:
// their product is averaged over 4³ points, with the voxel's own extinction σ between them, so the
// voxel that holds a lamp (whose centre would see none of it) scatters its share.
VoxelLight voxelIrradiance(const Light& light, const glm::dvec3& p, double h, double sigma, const Arrival& atCentre) {
    if (light.kind == gpu::LightKind::Directional || !(glm::length(light.position - p) < 2.0 * h)) {
        const double half = 0.5 * sigma * h;
        return {atCentre.irradiance, half > 1e-4 ? std::sinh(std::min(half, 30.0)) / half : 1.0};
    }
    constexpr int kSub = 4;
    glm::vec3 sum(0.0f);
    for (int k = 0; k < kSub * kSub * kSub; ++k) {
        const glm::dvec3 at(k % kSub, (k / kSub) % kSub, k / (kSub * kSub));
        const Arrival a = arrival(light, p + ((at + 0.5) / double(kSub) - 0.5) * h);
        // Depth relative to the centre's, kept above −30 as the sinh's is: e^30 fits a float, and a
        // point nearer the lamp in a dense voxel must not overflow it (the centre's e^{−τ} follows).
        sum += a.irradiance * static_cast<float>(std::exp(-std::max(sigma * (a.distance - atCentre.distance), -30.0)));
    }
    return {sum / static_cast<float>(kSub * kSub * kSub), 1.0};
}

}  // namespace nimbus::media
