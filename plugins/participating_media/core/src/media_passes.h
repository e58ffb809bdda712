#pragma once
// The plugin's GPU passes (one .cpp + one shader pair each).
#include <memory>
#include <vector>

#include "nimbus/gpu/gl_objects.h"
#include "nimbus/media/media_renderer.h"
#include "nimbus/render/frame_graph.h"
#include "local_light_programs.h"
#include "particle_buffer.h"

namespace nimbus::media {

// One light view's slices: the view, the slice range and count, and where its layers start.
struct SliceView {
    render::LightView view;
    glm::vec3 lightOrigin{0.0f};  // origin-relative light position (perspective views)
    int slices = 4;
    int firstLayer = 0;
};

// Attaches the ceil(slices/4) layers of `view` in `texture` as draw buffers 0.. of `framebuffer`,
// clears them to zero and binds the framebuffer (both slice passes render a view this way).
void bindSliceLayers(GLuint framebuffer, GLuint texture, const SliceView& view);
// Detaches them again, so the next view's attachment count starts clean.
void unbindSliceLayers(GLuint framebuffer, const SliceView& view);
// The uniforms both slice programs read for a view (shaders/media/light_slices.vert,
// block_slices.vert): 0 view, 2 params (perspective, depth near/far, slices), 3 half extent
// (media/view_rays.glsl), 4 slice resolution, 6 light origin.
void setSliceViewUniforms(GLuint program, const SliceView& view, int resolution);
// setSliceViewUniforms and the light view's projection (5) that light_slices.vert draws particles with.
void setParticleSliceUniforms(GLuint program, const SliceView& view, int resolution);

// Light slices (DESIGN.md §3 light-slice system): every slice view renders all particles once,
// additively, into ceil(K/4) layers of one RGBA32F array.
class LightSlicePass {
public:
    LightSlicePass();
    render::ResourceHandle add(render::FrameGraph& graph, const std::vector<SliceView>& views, int resolution,
                               const ParticleGpuBuffer& buffer);

private:
    gpu::Program program_;
    gpu::VertexArray vertexArray_ = gpu::createVertexArray();  // core profile: one must be bound
};

// The media target of one frame: full resolution, or reduced (seed 002's offscreen particles) and
// upsampled afterwards. A mode pass renders into `size`; texel i stands for full-resolution
// position (i + 0.5) · fullResScale.
struct MediaTarget {
    glm::ivec2 size{1};
    glm::vec2 fullResScale{1.0f};
    const char* name = "media_color";
};

// How `particles` mode shades (MediaRenderSettings says what each means).
struct ParticleShading {
    bool softParticles = true;
    bool layerLight = true;
};

// `particles` mode: sorted soft billboards into the media target (rgb in-scatter, a transmittance).
class ParticlePass {
public:
    ParticlePass();
    render::ResourceHandle add(render::FrameGraph& graph, render::FrameContext& context, const ParticleGpuBuffer& buffer,
                               ParticleShading shading, const MediaTarget& target);

private:
    LocalLightPrograms layerLight_;                  // MEDIA_LAYER_LIGHT: ParticleShading::layerLight
    std::unique_ptr<LocalLightPrograms> pointLight_;  // without it, built when first asked for
    gpu::VertexArray vertexArray_ = gpu::createVertexArray();
};

// Seed 002: the depth each reduced texel used, then a depth-aware upsampling to full resolution.
class MediaUpsamplePass {
public:
    MediaUpsamplePass();
    render::ResourceHandle add(render::FrameGraph& graph, render::FrameContext& context, render::ResourceHandle low,
                               const MediaTarget& target, float threshold);

private:
    gpu::Program depthProgram_;
    gpu::Program upsampleProgram_;
    gpu::VertexArray vertexArray_ = gpu::createVertexArray();
};

}  // namespace nimbus::media
