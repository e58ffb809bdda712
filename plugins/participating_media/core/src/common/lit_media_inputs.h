#pragma once
// What every mode pass that lights the medium itself declares and binds: the media target it
// writes, the scene depth it stops at, and the mesh shadow map and light slices it lights with.
#include "common/media_target.h"
#include "nimbus/gpu/frame_graph.h"
#include "nimbus/media/graph_frame.h"

namespace nimbus::media {

struct LitMediaInputs {
    gpu::ResourceHandle media, depth, shadowMap, slices;
};

// In a pass's setup: creates the target (RGBA32F, target.size) and reads the rest when the frame has them.
void declareLitMediaInputs(gpu::PassBuilder& builder, const GraphFrame& context, const MediaTarget& target, LitMediaInputs& d);
// In its execution: binds depth, shadow map and slices at their units (gpu_bindings.h).
void bindLitMediaInputs(const gpu::PassResources& resources, const LitMediaInputs& d);

}  // namespace nimbus::media
