#pragma once
// The light that arrives at a voxel of the multiple-scattering grid (common/environment_grid.h)
// from one light: its irradiance, direction and distance at a point (assets/light_model.h's
// formulas, which the core cannot include), and over a whole voxel.
//
// Does not: shadow (the caller applies the medium's transmittance and the mesh boxes).
#include <glm/glm.hpp>

#include "nimbus/media/host.h"

namespace nimbus::media {

// E at p from one light, with the direction towards it and its distance (infinite for a
// directional light; 0, with no light, at a point light's own position).
struct Arrival {
    glm::dvec3 toLight{0.0};
    double distance = 0.0;
    glm::vec3 irradiance{0.0f};
};
Arrival arrival(const Light& light, const glm::dvec3& p);

// What arrives over the voxel of side h around p, per unit of the transmittance at its centre:
// irradiance × scale.
struct VoxelLight {
    glm::vec3 irradiance{0.0f};
    double scale = 1.0;
};
VoxelLight voxelIrradiance(const Light& light, const glm::dvec3& p, double h, double sigma, const Arrival& atCentre);

}  // namespace nimbus::media
