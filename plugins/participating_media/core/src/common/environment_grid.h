#pragma once
// The light of the multiple-scattering model that the real-time passes read from a grid
// (docs/scene-format.md §2): a coarse grid over the medium holding, per voxel,
//   x:   the environment's unscattered light, the mean transmittance towards the outside along 14
//        directions (the 6 axes and the 8 diagonals), each direction that meets a mesh box counted
//        dark (its light would be mesh-reflected, which the model leaves out);
//   yzw: the radiance of light scattered two or more times, φ/4π per unit albedo, from the
//        diffusion of what the lights and the environment scatter first (common/diffusion.h),
//        δ-Eddington scaled: the forward peak (g² of the scattering) counts as unscattered light.
// and beside it, per voxel, how that light varies with direction (the P1 approximation):
//   xyz: a, with the source towards ω_out for phase asymmetry g being x·max(0, 1 + g a·ω_out),
//        x = L_amb·T̄ + φ/4π in luminance, a = (3F/4π − 3 L_amb m)/x with |a| kept ≤ 1 (so the
//        radiance is nowhere negative), F the diffusion's net flux and m the environment
//        transmittance's first moment over the 14 directions.
// A forward-scattering cloud's lit face sends its diffuse light back out towards a viewer on the
// sun's side, and its shadowed face the sky's light through it: isotropic, both were too dark.
// Single scattering of the lights stays per particle or voxel, where the passes evaluate it exactly.
//
// Does not: resolve anything finer than a voxel (scattered light is the smooth part of the
// medium's), look past the grid (nothing lies there), or see mesh shadows finer than the boxes.
#include <vector>

#include <glm/glm.hpp>

#include "common/diffusion.h"
#include "nimbus/media/host.h"
#include "nimbus/media/particle_set.h"
#include "nimbus/media/volume.h"

namespace nimbus::media {

struct EnvironmentGrid {
    glm::ivec3 size{0};
    glm::dvec3 min{0.0};   // world position of voxel 0's outer corner
    glm::dvec3 voxel{0.0}; // the same along every axis
    std::vector<glm::vec4> texels;   // per voxel, x fastest: as above
    std::vector<glm::vec4> directional;  // per voxel: xyz a (above), w unused
    std::vector<glm::vec3> fluence;  // φ
    int sweeps = 0;                  // the diffusion solve's sweeps this frame (0: the last frame's answer kept)
    bool warm = false;               // solved from the last frame's answer (DiffusionSolve::warmSweeps), not from its inputs alone
    float rescatter = 0.0f;          // ω·(1 − T̄) over the voxels, weighted by their first scattering: the share of it that scatters again
    // What the answer was solved for (solveEnvironmentGrid): every number of the medium, mesh boxes,
    // grid size and sweep budgets, and the lights and ambient. A frame with the same keeps it.
    std::vector<double> inputs;
    std::vector<Light> lights;
    glm::vec3 ambient{0.0f};

    bool empty() const { return size.x == 0; }
};

// What lights the medium: the host frame's lights, ambient and mesh boxes.
struct EnvironmentLighting {
    const std::vector<Light>* lights = nullptr;
    glm::vec3 ambient{0.0f};
    const std::vector<OccluderBox>* meshes = nullptr;
};

// The medium on a grid of `voxelsAlongLongest` voxels along its longest side plus one of padding
// around it: the particles' kernels sampled and scaled so each keeps its optical volume (small ones
// land on their nearest voxel), and each volume's extinction (its noise's included) at the centres.
MediumGrid voxelizeMedium(const ParticleSet& particles, const std::vector<Volume>& volumes, int voxelsAlongLongest);

// The grid for `medium`, its solve started from `solve.coarser` where given, else from zero.
void buildEnvironmentGrid(const MediumGrid& medium, const EnvironmentLighting& lighting, const DiffusionSolve& solve, EnvironmentGrid& grid);

// The medium voxelised and its grid built, the solve started from one on grids of half as many
// voxels, down to 4; `grid` holds the last frame's, kept when its medium and lighting are the same
// (so a frame's picture depends on that frame alone, and a still cloud costs no solve).
// With solve.warmSweeps, a frame whose medium, mesh boxes or lights moved a little starts from the
// last answer instead (its picture then depends on the frames before); a light that jumped or was
// switched, and the first frame after everything stops, are solved cold.
void solveEnvironmentGrid(const ParticleSet& particles, const std::vector<Volume>& volumes, const EnvironmentLighting& lighting,
                          int voxelsAlongLongest, DiffusionSolve solve, EnvironmentGrid& grid);

}  // namespace nimbus::media
