#pragma once
// The plugin's GPU passes (one .cpp + one shader pair each).
#include <array>
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

// The light slices in deposit form (the fast tiers), two passes that replace LightSlicePass: each
// particle is drawn once into each slab between two slice planes it reaches, as one R32F layer per
// slab (slice_plan.h appendSlabPieces); the prefix pass sums the slabs into the RGBA32F slices
// LightSlicePass writes. Per fragment one float instead of ceil(K/4) RGBA targets and K erf values.
// Needs ARB_shader_viewport_layer_array (gl_Layer from the vertex shader).
class LightSliceDepositPass {
public:
    LightSliceDepositPass();
    static bool supported();
    // `pieces`: every view's pieces, view v's from firstPiece[v] (firstPiece has views.size() + 1 entries).
    render::ResourceHandle add(render::FrameGraph& graph, const std::vector<SliceView>& views, int resolution,
                               const ParticleGpuBuffer& buffer, std::vector<std::uint32_t> pieces, std::vector<int> firstPiece);

private:
    gpu::Program program_;
    gpu::Texture kernelTable_;
    gpu::Buffer pieces_;
    std::size_t capacity_ = 0;
    std::vector<std::uint32_t> staging_;  // this frame's pieces, uploaded when the pass runs
    gpu::VertexArray vertexArray_ = gpu::createVertexArray();
};

// Sums each view's slabs into the optical depth up to each of its slice planes.
class LightSlicePrefixPass {
public:
    LightSlicePrefixPass();
    render::ResourceHandle add(render::FrameGraph& graph, const std::vector<SliceView>& views, int resolution,
                               render::ResourceHandle slabs);

private:
    gpu::Program program_;
    gpu::VertexArray vertexArray_ = gpu::createVertexArray();
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
// The exact particles program (particles.*), with the light integrated over each particle or taken at one point.
gpu::ProgramDesc particlesDesc(bool layerLight);

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

inline constexpr GLuint kParticleLightBinding = 10;
inline constexpr int kMaxFragmentLamps = 2;  // shaders/media/particle_light_layout.glsl MAX_FRAGMENT_LAMPS

// The lights the fast splats evaluate per fragment (−1: none): the first directional light's phase
// function (g = 0.99 peaks within a few pixels), and point and spot lights' 1/d² (near a lamp it
// peaks across a particle far more sharply than any fit follows).
struct FragmentLamps {
    GLint sun = -1;
    std::array<GLint, kMaxFragmentLamps> lamps{};
};
FragmentLamps fragmentLamps(const std::vector<assets::ResolvedLight>& lights);

// Per-particle lighting (the fast tiers): each particle's source fitted over its billboard, in draw
// order, from nine rays through it (`exact`: each shaded as particles.frag shades a pixel;
// `constant`: the centre ray alone, for particles a few pixels wide).
// The per-particle lighting program (particle_lighting.comp): balanced's exact chord integrals, one ray per particle.
gpu::ProgramDesc particleLightingDesc(bool exact, bool constant);

class ParticleLightingPass {
public:
    ParticleLightingPass();
    void add(render::FrameGraph& graph, render::FrameContext& context, const ParticleGpuBuffer& buffer, std::size_t particles,
             bool exact, bool constant, const FragmentLamps& lamps);
    void bind() const;  // the lighting buffer, for the splats

private:
    const gpu::Program& program(const std::vector<assets::ResolvedLight>& lights, bool exact, bool constant);
    std::unique_ptr<LocalLightPrograms> programs_[4];  // by exact + 2·constant, built when first asked for
    gpu::Buffer light_;
    std::size_t capacity_ = 0;
};

// Fast particles: the sorted billboards with per-vertex source and per-fragment opacity from the
// pre-integrated kernel table. `eyeInside`: some particle contains the eye (its segment starts there).
// The splat program (particle_splats.*): eye inside the medium, lamps per fragment, one ray per particle.
gpu::ProgramDesc particleSplatDesc(bool eyeInside, bool lamps, bool constant);

class ParticleSplatPass {
public:
    ParticleSplatPass();
    render::ResourceHandle add(render::FrameGraph& graph, render::FrameContext& context, const ParticleGpuBuffer& buffer,
                               const ParticleLightingPass& lighting, bool eyeInside, bool constant, const FragmentLamps& lamps,
                               const MediaTarget& target);

private:
    const gpu::Program& program(bool eyeInside, bool lamps, bool constant);
    gpu::Program programs_[8];  // by eyeInside + 2·lamps + 4·constant, built when first asked for
    gpu::Texture kernelTable_;
    gpu::VertexArray vertexArray_ = gpu::createVertexArray();
};

// `billboards` mode: sprites lit per particle without shadows, one sprite fetch per fragment,
// soft particles (the yardstick a typical engine ships).
class BillboardPass {
public:
    BillboardPass();
    render::ResourceHandle add(render::FrameGraph& graph, render::FrameContext& context, const ParticleGpuBuffer& buffer,
                               const MediaTarget& target);

private:
    gpu::Program program_;
    gpu::Texture kernelTable_;
    gpu::VertexArray vertexArray_ = gpu::createVertexArray();
};

// Seed 002: the view depth each reduced texel of the media target used, which the compose pass's
// depth-aware upsampling compares with each full-resolution pixel's.
class MediaDepthUsedPass {
public:
    MediaDepthUsedPass();
    render::ResourceHandle add(render::FrameGraph& graph, render::FrameContext& context, const MediaTarget& target);

private:
    gpu::Program program_;
    gpu::VertexArray vertexArray_ = gpu::createVertexArray();
};

}  // namespace nimbus::media
