#pragma once
// Light scattered two or more times, as a diffusion process (Stam, "Multiple scattering as a
// diffusion process"): on a coarse grid over the medium, the fluence φ of the light the first
// scattering releases obeys −∇·(D∇φ) + σ_a φ = Q, with D = 1 / (3 σ_t (1 − ω g)) and Q the first
// scattering's source (σ_s times the light that arrives unscattered). The radiance it adds to the
// medium's source is φ / 4π per unit albedo, the same in every direction.
//
// Discretised by finite volumes (harmonic-mean diffusivity across faces); where the medium meets
// empty voxels the fluence falls to zero at the extrapolated boundary 2D past the face (Marshak's
// condition). Solved by red-black successive over-relaxation from a given start (environment_grid.h
// starts it from a coarser grid's answer).
//
// Meshes are walls: the model's meshes reflect nothing into the medium, so scattered light that
// reaches one is gone. A face between two voxels whose centres a mesh's box lies between, and a
// voxel whose centre lies inside one, meet the fluence's boundary as empty space does (MeshWalls).
//
// Does not: keep the scattered light's direction (forward peaks of later orders are lost, which the
// single-scattering term carries for order 1), or resolve anything finer than a voxel.
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace nimbus::media {

// The medium sampled at voxel centres, x fastest.
// Rec. 709 luminance weights: the grid's scalar measures (fluence, flux, albedo) are taken in them.
inline const glm::vec3 kLuminanceWeights(0.2126f, 0.7152f, 0.0722f);

struct MediumGrid {
    glm::ivec3 size{0};
    glm::dvec3 min{0.0};   // world position of voxel 0's outer corner
    double voxel = 0.0;    // side, the same along every axis
    std::vector<float> sigma;              // σ_t, 1/m
    std::vector<glm::vec3> scattering;     // σ_s = σ_t · albedo
    std::vector<float> sigmaG;             // σ_t · g, for the mean asymmetry
    std::vector<glm::vec3> emission;       // σ_t · emitted radiance per unit optical depth

    std::size_t count() const { return sigma.size(); }
    std::size_t index(int x, int y, int z) const {
        return (static_cast<std::size_t>(z) * static_cast<std::size_t>(size.y) + static_cast<std::size_t>(y)) *
                   static_cast<std::size_t>(size.x) + static_cast<std::size_t>(x);
    }
};

// Per voxel of a MediumGrid: bit a (0..2) where a mesh lies between its centre and its neighbour's
// along +a, kInsideMesh where its centre lies inside a mesh. Empty: no mesh among the voxels.
using MeshWalls = std::vector<std::uint8_t>;
constexpr std::uint8_t kInsideMesh = 8;

struct EnvironmentGrid;

struct DiffusionSolve {
    int maxSweeps = 64;           // red-black sweep pairs at most
    float tolerance = 1e-5f;      // stop when no voxel's fluence moves by more than this × the largest
    const EnvironmentGrid* coarser = nullptr;  // environment_grid.h: a solve to start from, when there is no last frame's
    // environment_grid.h: > 0, a changed frame starts from the grid's last answer (resampled onto the
    // new grid) with at most this many sweeps instead of from a coarser grid's solve.
    int warmSweeps = 0;
    float overRelaxation = 1.9f;  // successive over-relaxation's factor, in (0, 2)
    const MeshWalls* walls = nullptr;  // the meshes among the voxels; null: none
};

// The net flux F = −D∇φ of the luminance of φ per voxel (zero where there is no medium): central
// differences inside, one-sided to zero at the extrapolated boundary where a neighbour is empty or
// behind a mesh.
// The radiance of the diffuse light is then (φ + 3F·ω)/4π (the P1 approximation), which the
// passes use to see forward-scattering media brighter where light leaves towards the eye.
std::vector<glm::vec3> diffusionFlux(const MediumGrid& medium, const std::vector<glm::vec3>& fluence, const MeshWalls* walls = nullptr);

// φ per voxel for first-scattering source `source` (W/m³ per channel, Q above), starting from
// `fluence` when it has the grid's size, else from zero. Returns the sweeps run.
int solveDiffusion(const MediumGrid& medium, const std::vector<glm::vec3>& source, std::vector<glm::vec3>& fluence,
                   const DiffusionSolve& solve = {});

}  // namespace nimbus::media
