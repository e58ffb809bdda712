#pragma once
// The `particle_splats` pass of the fast tiers (shaders/media/particle_splats.*).
#include "common/particle_buffer.h"
#include "common/media_target.h"
#include "nimbus/gpu/frame_graph.h"
#include "nimbus/gpu/gl_objects.h"
#include "nimbus/gpu/shader_program.h"
#include "nimbus/media/graph_frame.h"
#include "particles/particle_lighting_pass.h"

namespace nimbus::media {

// Fast particles: the sorted billboards with per-vertex source and per-fragment opacity from the
// pre-integrated kernel table. `eyeInside`: some particle contains the eye (its segment starts there).
// The splat program (particle_splats.*): eye inside the medium, lamps per fragment, one ray per particle.
gpu::ProgramDesc particleSplatDesc(bool eyeInside, bool lamps, bool constant);

class ParticleSplatPass {
public:
    ParticleSplatPass();
    gpu::ResourceHandle add(gpu::FrameGraph& graph, GraphFrame& context, const ParticleGpuBuffer& buffer,
                               const ParticleLightingPass& lighting, bool eyeInside, bool constant, const FragmentLamps& lamps,
                               const MediaTarget& target);

private:
    const gpu::Program& program(bool eyeInside, bool lamps, bool constant);
    gpu::Program programs_[8];  // by eyeInside + 2·lamps + 4·constant, built when first asked for
    gpu::Texture kernelTable_;
    gpu::VertexArray vertexArray_ = gpu::createVertexArray();
};

}  // namespace nimbus::media
