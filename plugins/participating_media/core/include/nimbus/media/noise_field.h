#pragma once
// The density field of a noise volume (a `volume` object's `noise`, docs/scene-format.md §3): a
// procedural pattern in the node's frame, thresholded by coverage and faded towards the shape's
// surface, scaling the medium's extinction. Two kinds:
//   value  fractal value noise: lattice values from an integer hash, blended with the quintic fade,
//          summed over octaves at doubling frequency and `gain` times the amplitude (Perlin, 1985);
//   sines  Gardner's sums of sines (Gardner, 1985): per axis Σ cᵢ (sin(2ⁱ ω x + φᵢ) + 1), each
//          phase φᵢ driven by the next axis's previous octave, the three sums multiplied (scaled to
//          a mean of ½ and saturated at 1).
// The same function runs on the CPU (the reference, the grids) and in GLSL
// (shaders/media/common/noise.glsl) with the same float operations in the same order, so both give
// the same bits for the same input: no texture filtering, no library sin (noiseSin below), no
// division on the GPU (reciprocals come in NoiseParams), and this file is built without
// floating-point contraction (a fused multiply-add rounds once where the GPU rounds twice).
//
// Does not: evolve the pattern (it drifts with `velocity`), or take the medium's albedo from it.
#include <cstdint>

#include <glm/glm.hpp>

namespace nimbus::media {

enum class NoiseKind : std::uint8_t { Value, Sines };

inline constexpr int kMaxNoiseOctaves = 12;

struct NoiseField {
    NoiseKind kind = NoiseKind::Value;
    int octaves = 4;           // 1..kMaxNoiseOctaves
    double frequency = 1.0;    // the first octave's cycles per metre (> 0)
    std::uint32_t seed = 0;
    double gain = 0.5;         // each octave's amplitude over the last's, (0, 1]
    double coverage = 0.0;     // [0, 1): the share of the pattern's range below which there is no medium
    double falloff = 0.0;      // [0, 1]: the share of the shape's half extent over which density fades to 0 at its surface
    glm::dvec3 velocity{0.0};  // m/s, node frame: the pattern drifts with it
};

// What the CPU and GLSL functions read: the field's numbers as floats, the reciprocals precomputed.
struct NoiseParams {
    std::uint32_t kind = 0, octaves = 1, seed = 0;
    float gain = 0.5f;
    float invAmplitude = 1.0f;  // 1 / Σ gainⁱ (value) or 4 / (2 Σ gainⁱ)³ (sines)
    float coverage = 0.0f;
    float invOneMinusCoverage = 1.0f;
    float invFalloff = 0.0f;  // 1 / falloff (box), 1 / (1 − (1 − falloff)²) (ellipsoid); 0: no fade
};
NoiseParams noiseParams(const NoiseField& field, bool ellipsoid);

// lowbias32 (Wellons): a 32-bit integer hash.
std::uint32_t noiseHash(std::uint32_t x);
// sin(x) from a Cody–Waite reduction and an odd polynomial, identical to the GLSL's.
float noiseSin(float x);
// The pattern in [0, 1] at p in noise units (node metres × frequency).
float noisePattern(const NoiseParams& params, glm::vec3 p);
// The density scale in [0, 1] at p, with `unit` the point in the shape's unit frame (the cube
// [−1, 1]³ or the unit sphere): the pattern thresholded by coverage and faded at the surface.
float noiseDensity(const NoiseParams& params, glm::vec3 p, glm::vec3 unit, bool ellipsoid);

}  // namespace nimbus::media
