#pragma once
// mini_host's mesh drawing: (1) depth of every mesh from every light view into one shadow-map
// array, (2) the opaque pass, Lambert with PCF shadows, into an RGBA32F colour and a D32F depth
// target. Reversed Z everywhere (depth 1 near, cleared to 0, GL_GREATER), positions relative to
// the camera. The media plugin's light transmittance is compiled in on request
// (MEDIA_LIGHT_TRANSMITTANCE); its slices must be bound before renderOpaque.
#include <map>

#include "frame_blocks.h"
#include "frame_input.h"
#include "gpu_meshes.h"
#include "nimbus/gpu/gl_objects.h"
#include "nimbus/gpu/shader_program.h"

namespace mini {

class MeshRenderer {
public:
    explicit MeshRenderer(const Scene& scene);

    // Uploads the frame's uniform blocks and renders the shadow-map array (none without views).
    void renderShadows(const FrameInput& frame);
    // Scene colour and depth; `mediaTransmittance` picks the shader variant with the media hook.
    void renderOpaque(const FrameInput& frame, bool mediaTransmittance);

    GLuint shadowMap() const { return shadowMap_.id(); }  // 0 when no light has views
    GLuint sceneColor() const { return color_.id(); }
    GLuint sceneDepth() const { return depth_.id(); }

private:
    struct DrawState {
        GLuint program;
        bool material;  // cull single-sided back faces, set the base colour and the normal matrix
    };
    void drawInstances(const FrameInput& frame, const DrawState& state) const;
    const nimbus::gpu::Program& opaqueProgram(bool mediaTransmittance);
    void ensureTargets(int width, int height);

    GpuMeshes meshes_;
    FrameBlocks blocks_;
    nimbus::gpu::Program shadowProgram_;
    std::map<bool, nimbus::gpu::Program> opaquePrograms_;
    nimbus::gpu::Sampler compareSampler_;
    nimbus::gpu::Texture shadowMap_, color_, depth_;
    nimbus::gpu::Framebuffer framebuffer_;
};

// The ProgramDesc of one of mini_host's shaders: its own folder first, then Nimbus's shaders folder
// (only the media include is taken from there).
nimbus::gpu::ProgramDesc miniProgram(const char* vertex, const char* fragment);

}  // namespace mini
