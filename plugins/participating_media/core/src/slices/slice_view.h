#pragma once
// A light view's slices and how the slice passes bind and describe them to their programs.
#include <algorithm>

#include "common/shared_frame.h"
#include "nimbus/gpu/gl_objects.h"
#include "nimbus/gpu/pipeline_state.h"

namespace nimbus::media {

// Attaches `count` (at most 8) layers of `texture` from `firstLayer` as draw buffers 0.. of
// `framebuffer` and binds it; detachSliceLayers detaches them again.
void attachSliceLayers(GLuint framebuffer, GLuint texture, int firstLayer, int count);
void detachSliceLayers(GLuint framebuffer, int count);
// A view's texels per side in an array of `arrayResolution`: its own (SliceView::resolution), drawn
// into the first texels of its layers, or the array's. The lookups read it there
// (shaders/media/host/light_transmittance.glsl mediaSliceLayerUv).
inline int sliceTexels(const SliceView& view, int arrayResolution) {
    return view.resolution > 0 ? std::min(view.resolution, arrayResolution) : arrayResolution;
}
// Attaches the ceil(slices/4) layers of `view` in `texture` as draw buffers 0.. of `framebuffer`,
// clears them to zero unless a pass adds to what an earlier one drew (`clear` false), and binds
// the framebuffer (every slice pass renders a view this way). A view of fewer texels than the
// array leaves the rest of its layers zero: a lookup's bilinear tap weighs the first of them 0.
void bindSliceLayers(GLuint framebuffer, GLuint texture, const SliceView& view, bool clear = true);
// Optical depth adds, so slices need no sort: additive blending on every draw buffer.
inline constexpr gpu::PipelineState kSliceAdd = gpu::PipelineState::blending(gpu::kAdditive);
// The state slice draws add optical depth with: a resolution² viewport and kSliceAdd.
void setAdditiveSliceState(int resolution);
// Detaches them again, so the next view's attachment count starts clean.
void unbindSliceLayers(GLuint framebuffer, const SliceView& view);
// The uniforms both slice programs read for a view (shaders/media/slices/light_slices.vert,
// block_slices.vert): 0 view, 2 params (perspective, depth near/far, slices), 3 half extent
// (media/common/view_rays.glsl), 4 slice resolution, 6 light origin.
void setSliceViewUniforms(GLuint program, const SliceView& view, int resolution);
// setSliceViewUniforms and the light view's projection (5) that light_slices.vert draws particles with.
void setParticleSliceUniforms(GLuint program, const SliceView& view, int resolution);

}  // namespace nimbus::media
