#pragma once
#include <functional>
#include <map>
#include <string>
#include <utility>
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
    // Depth only, or with an alpha cutout (material_binding.h shadowFeatures), compiled on first use.
    const gpu::Program& program(unsigned features);
    std::map<unsigned, gpu::Program> programs_;
    gpu::Sampler compareSampler_;
    friend class OpaquePass;
};

// glTF metallic-roughness meshes with shadows into the output + scene depth (docs/design.md §3 step 2).
class OpaquePass {
public:
    OpaquePass();
    void add(FrameGraph& graph, FrameContext& context, const ShadowPass& shadows, const gpu::Texture& output);

private:
    // What a program is compiled for: a material's features (material_binding.h), the extensions'
    // mesh shading defines, and the frame's lighting (shaders/opaque.frag VERTEX_LIGHTS,
    // FRAGMENT_LIGHTS, POINT_FRAGMENT_LIGHTS, PCF_RADIUS), all fixed at compile time because llvmpipe runs both sides of a branch.
    struct Variant {
        unsigned features = 0;
        std::vector<std::string> extensions;
        int vertexLights = 0;
        unsigned directionalMask = 0;  // bit i: vertex light i is directional
        bool fragmentLights = false;
        bool pointFragmentLights = false;  // every fragment light is a point light (six views or none)
        int pcfRadius = 0;
        auto operator<=>(const Variant&) const = default;
    };
    static Variant frameVariant(const FrameContext& context);  // all but the material's features
    const gpu::Program& program(const Variant& variant);      // compiled when first asked for
    std::map<Variant, gpu::Program> programs_;
};

// The scissor rects compose draws over a `size` viewport, each with whether it takes the edge
// variant: `composed` (the layer's cover, or the viewport with fog) cut into the edge rect and the
// strips around it; no rect outside `composed`.
std::vector<std::pair<glm::ivec4, bool>> composeRects(glm::ivec2 size, glm::ivec4 composed, glm::ivec4 edgeRect);

// media (and fog) blended over the opaque image in the persistent output (docs/design.md §3 step 4).
class ComposePass {
public:
    ComposePass();
    void add(FrameGraph& graph, FrameContext& context);

private:
    enum Variant { kLayer = 1, kUpsample = 2, kFog = 4, kEdges = 8 };

    const gpu::FullscreenPass& pass(int variant);  // compiled on first use
    static void draw(const gpu::FullscreenPass& pass, int variant, GLuint framebuffer, glm::ivec2 size, glm::vec2 scale, float threshold,
                     glm::ivec4 edgeRect);

    std::map<int, gpu::FullscreenPass> passes_;
    gpu::Sampler clampedNearest_;  // the upsampling gathers depths at the layer's edges
};

// Draws every instance's primitives, each with the program `options.program` picks for its material
// and the material bound for it (material_binding.h), uModel at location 0 and, when
// `normalMatrixLocation` ≥ 0, the normal matrix. Skips back faces of single-sided materials when
// `cullSingleSided`; `shading`: the opaque pass's material terms, else the shadow pass's cutout.
struct DrawOptions {
    int normalMatrixLocation = -1;
    bool cullSingleSided = false;
    bool shading = false;
    // The program for a primitive, and the features it was compiled with.
    std::function<std::pair<GLuint, unsigned>(const GpuMaterial&, const GpuPrimitive&)> program;
};
void drawInstances(const FrameContext& context, const DrawOptions& options);

}  // namespace nimbus::render
