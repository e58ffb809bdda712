#pragma once
// `raymarch` mode's grid (Jendersie): the medium sampled at voxel centres, σ_t with the σ-weighted
// albedo, emission and phase asymmetry, for the GPU to interpolate trilinearly. Particles add their
// kernels at the centres; a constant volume adds its σ times the share of the voxel it covers, so
// its faces land between voxel centres where they lie rather than on the nearest one. Noise volumes
// set the grid's bounds but are left to the GPU (raymarch_noise_pass.h).
//
// Does not: filter particles (a voxel holds the kernel sums at its centre) or keep more than one
// phase function (mixed media march with Henyey–Greenstein).
#include <vector>

#include <glm/glm.hpp>

#include "nimbus/media/particle_set.h"
#include "nimbus/media/volume.h"

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
// deviation; 10th percentile), with the longest side at most `kMaxAutoVoxels` voxels; with a volume
// (whose faces are sharp) the longest side gets all of them.
inline constexpr int kMaxAutoVoxels = 96;
// A voxel that a volume's surface crosses is covered by the share of these sub-samples (per axis)
// inside it.
inline constexpr int kCoverageSamples = 4;

// `voxelsAlongLongest` > 0 fixes the grid's longest side; 0 chooses it from the medium.
// A voxel of padding surrounds the medium, so the grid fades to zero at its faces.
VoxelGrid voxelize(const ParticleSet& particles, const std::vector<Volume>& volumes, int voxelsAlongLongest);

}  // namespace nimbus::media
