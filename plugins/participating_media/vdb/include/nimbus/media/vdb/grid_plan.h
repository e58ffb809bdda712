#pragma once
// Where and how finely the medium is voxelised for export (medium_grids.h): the voxel side, and
// how many voxels that would take, before anything is allocated. Voxel (i, j, k) is centred on the
// world point (i, j, k) · voxel: OpenVDB's index space has voxel centres at integer coordinates,
// so a plain scale transform maps every index to the centre it was sampled at.
//
// Does not: allocate the grids, or refuse anything itself: a plan that does not fit says so
// (`fits`) and names the smallest voxel that would, for the caller's message.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "nimbus/base/aabb.h"
#include "nimbus/media/particle_set.h"
#include "nimbus/media/volume.h"

namespace nimbus::media::vdb {

// The most voxels an export may hold (an upper estimate of the active voxels, below): 2²⁷, about
// 2 GiB for the density and a colour grid together while they are built.
inline constexpr double kMaxVoxels = 134217728.0;
// What an automatic voxel aims under (2²⁴): coarser than asked rather than a file of gigabytes.
inline constexpr double kAutoVoxels = 16777216.0;
// Index coordinates are 32-bit: the medium must lie within this many voxels of the world origin.
inline constexpr double kMaxIndex = 1073741824.0;  // 2³⁰

// The automatic voxel (docs/export.md): the finest of
//   particles: a sixth of the small particles' radius (10th percentile), so the trilinear read of a
//              lone particle errs at most 1 − exp(−9h²/4R²) ≈ 6% of its optical depth (kernelError);
//   volumes:   a 32nd of the volume's smallest world extent, and for noise a quarter of the finest
//              octave's wavelength;
// coarsened until the estimate is under kAutoVoxels.
inline constexpr double kParticleVoxelsPerRadius = 6.0;
inline constexpr double kVolumeVoxelsAcross = 32.0;
inline constexpr double kNoiseVoxelsPerWavelength = 4.0;

struct GridPlan {
    double voxel = 0.0;       // metres, the side of every voxel
    bool automatic = false;   // chosen from the medium (no voxel asked)
    bool coarsened = false;   // automatic, and made coarser than the medium asks to fit kAutoVoxels
    Aabb bounds;              // the medium's world bounds
    glm::ivec3 indexMin{0};   // inclusive index box of the voxel centres inside `bounds`
    glm::ivec3 indexMax{-1};
    double boxVoxels = 0.0;        // voxels in the index box
    double estimatedVoxels = 0.0;  // upper estimate of the active voxels: each particle's cube and each volume's box, at most boxVoxels
    bool fits = false;             // estimatedVoxels <= the limit asked and the index box within ±kMaxIndex
    double smallestVoxel = 0.0;    // the smallest voxel that fits the limit (for the message when !fits)
};

// `voxel` > 0 asks for that side; 0 chooses it (above). `limit` is the most voxels a plan may
// estimate; an automatic voxel also stays under kAutoVoxels. An empty medium gives an empty plan that does not fit.
GridPlan planGrid(const ParticleSet& particles, const std::vector<Volume>& volumes, double voxel = 0.0, double limit = kMaxVoxels);

// The worst relative error of a lone particle's optical depth read through a grid of side `voxel`
// with trilinear interpolation, against its closed form through the centre: the kernel is a
// Gaussian of s = R/3, and linear interpolation across the two axes perpendicular to a ray
// flattens its peak by at most 1 − exp(−voxel²/8s²) each.
double kernelError(double voxel, double radius);

}  // namespace nimbus::media::vdb
