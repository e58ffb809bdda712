#pragma once
// The participating medium as OpenVDB grids in world metres (docs/export.md): what `sandbox export`
// writes, for path tracers and DCC tools. Every grid shares the plan's transform (grid_plan.h):
// voxel (i, j, k) holds the medium at its centre, the world point (i, j, k) · voxel.
//   density   σ_t in 1/m: each particle's kernel σ exp(−4.5 r²/R²), r < R, at the centre, plus
//             each volume's extinction there. A voxel that a volume's surface crosses holds the
//             mean over kSurfaceSamples³ points in it instead, so a face lies where it is to
//             a fraction of a voxel rather than at the nearest centre. Active where > 0, background 0.
//   albedo    Vec3, the σ-weighted mean single-scattering albedo of what lies at the voxel;
//   emission  Vec3, the σ-weighted mean emission (radiance per unit optical depth, as the scene's);
//   g         float, the σ-weighted mean Henyey–Greenstein asymmetry (a Rayleigh medium counts 0).
// Each of the last three is a grid only where it varies across the medium; where every particle
// and volume has the same value it is metadata of `density` under the same name instead.
//
// Does not: filter the particles (a voxel is a point sample, as a renderer's trilinear read
// expects), or keep light, meshes or the phase function's shape beyond g (metadata "phase").
#include <filesystem>
#include <string>
#include <vector>

#include <openvdb/openvdb.h>

#include "nimbus/media/particle_set.h"
#include "nimbus/media/vdb/grid_plan.h"
#include "nimbus/media/volume.h"

namespace nimbus::media::vdb {

// Sub-samples per axis over a voxel that a volume's surface crosses: a constant volume's face
// lands within 1/16 of a voxel of where it lies along each axis. A noise volume, whose field
// varies within a voxel anyway, takes 4 (each of its samples costs a noise evaluation).
inline constexpr int kSurfaceSamples = 8;
inline constexpr int kNoiseSurfaceSamples = 4;

struct MediumGrids {
    openvdb::FloatGrid::Ptr density;   // always
    openvdb::Vec3SGrid::Ptr albedo;    // null: uniform, metadata "albedo" of density
    openvdb::Vec3SGrid::Ptr emission;  // null: uniform, metadata "emission"
    openvdb::FloatGrid::Ptr g;         // null: uniform, metadata "g"

    openvdb::GridPtrVec grids() const;  // the non-null ones, density first
};

// The grids of the medium at the plan's voxel. `plan` must fit (planGrid; std::invalid_argument
// otherwise, before anything is allocated). `progress` draws a bar on stderr (a terminal only).
MediumGrids buildMediumGrids(const ParticleSet& particles, const std::vector<Volume>& volumes, const GridPlan& plan,
                             bool progress = false);

// Where the file came from, kept as file metadata ("nimbus_scene", "nimbus_time").
struct ExportInfo {
    std::string scene;
    double time = 0.0;
};

// Writes the grids to `path` through a temporary file beside it, renamed into place, so a failed
// write leaves no partial file. InputError naming the file when it cannot be written.
void writeVdb(const std::filesystem::path& path, const MediumGrids& grids, const ExportInfo& info);

}  // namespace nimbus::media::vdb
