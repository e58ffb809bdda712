#pragma once
// The `media_seam_marks` pass (shaders/media/upsample/seam_marks.vert, seam_marks.frag).
#include <cstdint>
#include <vector>

#include "common/media_target.h"
#include "common/particle_buffer.h"
#include "nimbus/gpu/frame_graph.h"
#include "nimbus/gpu/gl_objects.h"
#include "nimbus/media/graph_frame.h"
#include "nimbus/media/host.h"

namespace nimbus::media {

// Mixed resolution where a mesh lies inside the medium. A reduced texel computed at the depth of
// a surface inside a particle is no depth edge, yet it spreads the kernel cut there, and the light
// the mesh changes, over the pixels around it: most of the seam band's error at ½ and ¼. So the
// texels whose surface lies inside the sphere of a particle in `particles` (those a mesh's box
// enters) are marked in `depthUsed` (MediaDepthUsedPass's) as computed at no pixel's depth; the
// edge stencil (MediaEdgeStencilPass) then marks every pixel that reads them, and the technique
// draws the medium there again at full resolution. A surface the reduced medium all but hides is
// not marked (seam_marks.frag).
//
// Does not: test the mesh itself (a box entering a sphere whose surface lies outside it marks
// nothing), or run where the technique draws no edges (its edge rect holds every marked texel).
class MediaSeamMarksPass {
public:
    MediaSeamMarksPass();
    // After MediaDepthUsedPass::add, before MediaEdgeStencilPass::add; returns `depthUsed`, written to.
    gpu::ResourceHandle add(gpu::FrameGraph& graph, GraphFrame& context, const ParticleGpuBuffer& buffer, std::vector<std::uint32_t> particles,
                            gpu::ResourceHandle depthUsed, const MediaTarget& target);

private:
    gpu::Program program_;
    gpu::VertexArray vertexArray_ = gpu::createVertexArray();
    gpu::Buffer particles_;
    std::size_t capacity_ = 0;
};

// The indices of the particles whose sphere some mesh box enters, for MediaSeamMarksPass.
std::vector<std::uint32_t> particlesCutByMeshes(const std::vector<OccluderBox>& meshes, const ParticleSet& particles);

}  // namespace nimbus::media
