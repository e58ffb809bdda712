#pragma once
// The `billboards` pass (shaders/media/billboards.*).
#include "common/particle_buffer.h"
#include "common/media_target.h"
#include "nimbus/gpu/frame_graph.h"
#include "nimbus/gpu/gl_objects.h"
#include "nimbus/media/graph_frame.h"

namespace nimbus::media {

// `billboards` mode: sprites lit per particle without shadows, one sprite fetch per fragment,
// soft particles (the yardstick a typical engine ships).
class BillboardPass {
public:
    BillboardPass();
    gpu::ResourceHandle add(gpu::FrameGraph& graph, GraphFrame& context, const ParticleGpuBuffer& buffer,
                               const MediaTarget& target);

private:
    gpu::Program program_;
    gpu::Texture kernelTable_;
    gpu::VertexArray vertexArray_ = gpu::createVertexArray();
};

}  // namespace nimbus::media
