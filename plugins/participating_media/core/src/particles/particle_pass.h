#pragma once
// The `particles` pass: the exact tier (shaders/media/particles.*).
#include <memory>

#include "common/local_light_programs.h"
#include "common/particle_buffer.h"
#include "common/media_target.h"
#include "nimbus/gpu/frame_graph.h"
#include "nimbus/gpu/gl_objects.h"
#include "nimbus/gpu/shader_program.h"
#include "nimbus/media/graph_frame.h"

namespace nimbus::media {

// How `particles` mode shades (MediaRenderSettings says what each means).
struct ParticleShading {
    bool softParticles = true;
    bool layerLight = true;
};

// `particles` mode: sorted soft billboards into the media target (rgb in-scatter, a transmittance).
// The exact particles program (particles.*), with the light integrated over each particle or taken at one point.
gpu::ProgramDesc particlesDesc(bool layerLight);

class ParticlePass {
public:
    ParticlePass();
    gpu::ResourceHandle add(gpu::FrameGraph& graph, GraphFrame& context, const ParticleGpuBuffer& buffer,
                               ParticleShading shading, const MediaTarget& target);

private:
    LocalLightPrograms layerLight_;                  // MEDIA_LAYER_LIGHT: ParticleShading::layerLight
    std::unique_ptr<LocalLightPrograms> pointLight_;  // without it, built when first asked for
    gpu::VertexArray vertexArray_ = gpu::createVertexArray();
};

}  // namespace nimbus::media
