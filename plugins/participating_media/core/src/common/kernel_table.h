#pragma once
// Pre-integrated kernel segments (the sheet-buffer splatting paper, docs/references.md): the optical depth of
// one particle of unit radius and unit peak extinction along a ray at impact parameter β (radii), from where
// the ray enters the sphere up to μ radii past its closest point. The fast splats
// (shaders/media/common/kernel_table.glsl) read it bilinearly, so a fragment's opacity costs one fetch instead
// of two erf evaluations.
#include <vector>

#include "nimbus/gpu/gl_objects.h"

namespace nimbus::media {

// The closed form: e^(−4.5β²) ∫ e^(−4.5s²) ds over [−h, clamp(μ, −h, h)], h = √(1 − β²); 0 for β ≥ 1.
double kernelSegment(double beta, double mu);

// Texel (i, j) holds kernelSegment(i/(betas − 1), 2j/(mus − 1) − 1): the table's corners are the
// domain's, so a bilinear fetch at (β(betas − 1) + 0.5)/betas is exact at every sample.
std::vector<float> kernelTableValues(int betas, int mus);

inline constexpr int kKernelTableBetas = 64;
inline constexpr int kKernelTableMus = 128;

// The table as an R32F texture with linear filtering and clamped edges.
gpu::Texture createKernelTable();

}  // namespace nimbus::media
