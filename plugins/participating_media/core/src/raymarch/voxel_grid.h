#pragma once
// `raymarch` mode's grid (Schpok et al.): the particles' medium sampled at voxel centres, σ_t with the
// σ-weighted albedo, emission and phase asymmetry, for the GPU to interpolate trilinearly.
//
// Does not: filter (a voxel holds the kernel sums at its centre) or keep more than one phase
// function (mixed media march with Henyey–Greenstein).
#include <vector>

#include <glm/glm.hpp>

#include "nimbus/media/particle_set.h"

namespace nimbus::media {

struct VoxelGrid {
    glm::ivec3 size{0};
    glm::dvec3 min{0.0};    // world position of the grid's corner (voxel 0's outer corner)
    glm::dvec3 voxel{0.0};  // extent of one voxel, the same along every axis
    std::vector<glm::vec4> scattering;  // per voxel: rgb σ_t·albedo, a σ_t (1/m)
    std::vector<glm::vec4> emission;    // per voxel: rgb σ_t·emission, a σ_t·g
    bool rayleigh = false;              // every particle scatters with the Rayleigh phase

    bool empty() const { return size.x == 0; }
};

// The voxel side when none is asked: a third of the small particles' radius (the kernel's standard
// deviation; 10th percentile), with the longest side at most `kMaxAutoVoxels` voxels.
inline constexpr int kMaxAutoVoxels = 96;

// `voxelsAlongLongest` > 0 fixes the grid's longest side; 0 chooses it from the particle size.
// A voxel of padding surrounds the particles' spheres, so the grid fades to zero at its faces.
VoxelGrid voxelize(const ParticleSet& particles, int voxelsAlongLongest);

}  // namespace nimbus::media
