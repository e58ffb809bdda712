#pragma once
// A light's second, finer slice view where meshes reach into the medium (the seam band). One slice
// array holds every view at one resolution, so a view over the whole medium is coarse where a wing
// cuts it. The crop is the same orthographic view narrowed to the meshes' overlap with the medium,
// from a little before it to past it, with its planes closer: its texels and slice spacing are up
// to kCropGain finer there. Its first plane takes the optical depth before it from the whole view
// (the seed), so only the particles past it are drawn again. The lookups read it inside its
// footprint and depth range and the whole view elsewhere (shaders/media/host/light_transmittance.glsl).
//
// Does not: crop a point or spot light's views (their texels are already finest near the lamp),
// or blend the two views at the crop's border (each side reads one).
#include <optional>
#include <vector>

#include "nimbus/gpu/light_views.h"
#include "nimbus/media/host.h"

namespace nimbus::media {

// How much finer than the whole view a crop is at most, across (texels) and in depth (spacing):
// the detail that took the seam band near exact's (docs/design-notes.md). A finer crop would pay
// for texels the seam does not need.
inline constexpr double kCropGain = 2.0;
// The crop is kept only where it is at least this many times narrower than the whole view across,
// or shallower in depth: a crop as wide and deep would be the whole view again, at its cost.
inline constexpr double kMinCropGain = 1.5;

struct SliceCrop {
    gpu::LightView view;
    int slices = 0;
};

// `whole`: a directional light's view of the medium (`medium`, world space; `origin` the camera's,
// as the views are origin-relative) with `wholeSlices` slices. The crop shares its orientation and
// view depth, covers the mesh boxes' overlap with the medium grown by `margin` (metres: the
// particles that reach the meshes), widened to 1/kCropGain of the whole view where it is narrower.
// Its slice planes run kCropGain closer than the whole view's (at most kMaxSlices) from `margin`
// before that overlap (plane 1: a particle reaching a mesh lies wholly past it) to past the overlap;
// its near plane lies one spacing before plane 1 and is never read. Empty for a perspective view,
// where no mesh box reaches into the medium, or where the overlap is neither kMinCropGain narrower
// nor shallower than the medium.
// A crop's first plane, the depth its seed is taken at and from which lookups read it: one spacing
// past its near plane.
inline double cropFirstPlane(const gpu::LightView& crop, int slices) {
    return crop.depthNear + (static_cast<double>(crop.depthFar) - crop.depthNear) / slices;
}

std::optional<SliceCrop> meshCropView(const gpu::LightView& whole, int wholeSlices, const std::vector<OccluderBox>& meshes, const Aabb& medium,
                                      double margin, const glm::dvec3& origin);

}  // namespace nimbus::media
