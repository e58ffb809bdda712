#pragma once
#include <map>
#include <string>
#include <vector>
// The engine's own passes (one .cpp and one set of .glsl files each).
#include "nimbus/gpu/gl_objects.h"
#include "nimbus/gpu/fullscreen_pass.h"
#include "nimbus/render/scene_renderer.h"

namespace nimbus::render {

// Depth from every light view into one D32F array (docs/design.md §3 step 1).
class ShadowPass {
public:
    ShadowPass();
    void add(FrameGraph& graph, FrameContext& context);

private:
    gpu::Program program_;
    gpu::Sampler compareSampler_;
    friend class OpaquePass;
};

// Lambert meshes with shadows into scene colour + depth (docs/design.md §3 step 2).
class OpaquePass {
public:
    OpaquePass();
    void add(FrameGraph& graph, FrameContext& context, const ShadowPass& shadows);

private:
    // The program with the extensions' mesh shading defines, compiled when first asked for.
    const gpu::Program& program(const std::vector<MeshShadingInput>& inputs);
    std::map<std::vector<std::string>, gpu::Program> programs_;
};

// media over opaque into the persistent output (docs/design.md §3 step 4).
class ComposePass {
public:
    ComposePass();
    void add(FrameGraph& graph, FrameContext& context, const gpu::Texture& output);

private:
    enum Variant { kLayer = 1, kUpsample = 2, kFog = 4 };

    const gpu::FullscreenPass& pass(int variant);  // compiled on first use

    std::map<int, gpu::FullscreenPass> passes_;
    gpu::Sampler clampedNearest_;  // the upsampling gathers depths at the layer's edges
};

// Draws every instance's primitives with uModel (location 0) and, when `normalMatrixLocation` ≥ 0,
// the normal matrix; `perMaterial` sets material uniforms. Skips back faces of single-sided
// materials when `cullSingleSided`.
struct DrawOptions {
    int normalMatrixLocation = -1;
    bool cullSingleSided = false;
    bool bindMaterial = false;
};
void drawInstances(const FrameContext& context, GLuint program, const DrawOptions& options);

}  // namespace nimbus::render
