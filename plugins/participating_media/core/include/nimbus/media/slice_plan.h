#pragma once
// How many light slices a medium needs (docs/design.md §3 "slice count follows from the scene").
//
// Slices hold optical depth at K planes across the medium's depth range from the light; in between,
// τ is interpolated linearly. Two things make that interpolation wrong: a slice spacing larger than
// the particles (τ rises over one particle's diameter as an erf curve, the more steeply the denser
// the particle), and a large optical depth per slice (the error in τ becomes a large error in e^−τ). So
//     K = clamp(roundUpTo4(max(depth extent / mean radius, depth extent · max_p √τ_p / (0.27 R_p),
//                              2 · τ_column)), 4, 32)
// where τ_p is one particle's peak optical depth and τ_column the largest optical depth along one
// light ray, estimated on a 32×32 grid across the light's view of the medium.
#include <cstdint>
#include <vector>

#include "nimbus/media/particle_set.h"
#include "nimbus/media/volume.h"
#include "nimbus/gpu/light_views.h"

namespace nimbus::media {

inline constexpr int kMinSlices = 4;
inline constexpr int kMaxSlices = 32;  // 8 render targets × 4 channels in one pass

struct SliceEstimate {
    double depthNear = 0.0;     // the medium's view-depth range from the light (slices span it)
    double depthFar = 0.0;
    double depthExtent = 0.0;   // depthFar − depthNear
    double meanRadius = 0.0;
    double columnDepth = 0.0;   // τ_column
    int slices = kMinSlices;
    double medianSpan = 0.0;    // the median particle's radius across the view: metres (orthographic)
                                // or tan of its angular radius from the light (perspective)
};

// The slice resolution that puts `texelsPerRadius` texels across the median particle's radius
// (slice_resolution=auto), a multiple of 16 in [minimum, 256]: a lamp's cube faces need far fewer
// texels than the fixed 256 where its particles subtend degrees.
inline constexpr int kMinSliceResolution = 32;
int sliceResolutionFor(const SliceEstimate& estimate, const gpu::LightView& view, double texelsPerRadius,
                       int minimum = kMinSliceResolution);

// `view` is a light view of the medium; `origin` the frame origin its matrices are relative to.
SliceEstimate estimateSlices(const ParticleSet& particles, const gpu::LightView& view, const glm::dvec3& origin);
// The same with volumes (volume.h) too: the depth range covers their boxes, the particles' slice
// spacing is kept across it, and a volume's column (σ times its longest chord) counts as τ_column.
SliceEstimate estimateSlices(const ParticleSet& particles, const std::vector<Volume>& volumes, const gpu::LightView& view,
                             const glm::dvec3& origin);

// The deposit form of the slices (light_slice_deposit_pass.cpp): every particle is drawn once into
// each slab, between two consecutive slice planes, that its sphere reaches. Slab k spans view depth
// [near + k·h, near + (k + 1)·h] (h = (far − near)/slices); the first reaches back to the light and
// the last past the medium, so each particle's whole optical depth lands somewhere.
inline constexpr std::uint32_t kSlabBits = 5;  // pieces pack particle << 5 | slab (slices ≤ 32)

struct SlabRange {
    int first = 0;  // the slab of the sphere's nearest depth
    int last = -1;  // of its farthest; last < first: the view never sees the particle
};
SlabRange particleSlabs(double depth, double radius, bool perspective, double depthNear, double depthFar, int slices);

// Appends the pieces of one view (particle << kSlabBits | slab), in particle order, from slab
// `firstSlab` on: a seeded crop's first slab holds its seed instead (light_slice_prefix_pass.h).
void appendSlabPieces(const ParticleSet& particles, const gpu::LightView& view, const glm::dvec3& origin, int slices,
                      std::vector<std::uint32_t>& pieces, int firstSlab = 0);

}  // namespace nimbus::media
