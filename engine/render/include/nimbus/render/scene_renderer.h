#pragma once
// The frame of docs/design.md §3 as a frame graph: mesh shadow maps → opaque (+ scene depth) →
// extensions (the media plugin) → compose into a linear RGBA32F output. Extensions add their own
// passes before the opaque pass (e.g. light slices that shadow meshes) and after it (the medium).
//
// Does not: own the scene or the camera (the caller passes a FrameInput each frame), present to a
// window (the editor blits output()), or encode images (assets/image_io does).
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "nimbus/assets/scene.h"
#include "nimbus/assets/scene_queries.h"
#include "nimbus/assets/image_io.h"
#include "nimbus/gpu/frame_graph.h"
#include "nimbus/gpu/texture_pool.h"
#include "nimbus/render/frame_data.h"
#include "nimbus/render/gpu_scene.h"
#include "nimbus/render/light_views.h"
#include "nimbus/render/view.h"

namespace nimbus::render {

using gpu::FrameGraph;
using gpu::PassBuilder;
using gpu::PassResources;
using gpu::PassTimer;
using gpu::ResourceHandle;
using gpu::TexturePool;

// Zero values take the defaults noted.
struct RenderSettings {
    int width = 0;           // 0: 1280
    int height = 0;          // 0: 720
    int shadowMapSize = 0;   // 0: 2048
    // A point light's cube faces' side as a share of shadowMapSize, each face drawn in the first
    // texels of its layer. A face spans 90°, so half the side still keeps finer texels than a sun's
    // one view over the whole scene. 0: 1.
    float pointShadowScale = 0.0f;
    int pcfRadius = -1;      // −1: 1 (3×3 taps)
};

// A point light's cube faces' side in texels (RenderSettings::pointShadowScale of shadowMapSize).
int pointShadowSize(const RenderSettings& settings);

struct FrameInput {
    const GpuScene* gpuScene = nullptr;
    std::vector<MeshInstance> instances;
    std::vector<assets::ResolvedLight> lights;
    assets::ResolvedCamera camera;
    assets::Environment environment;
};

// A translucent layer an extension puts over the opaque scene: premultiplied radiance in rgb and
// transmittance in a, so compose writes layer.rgb + layer.a · opaque. At a reduced resolution it
// comes with the view depth each texel was computed at, and compose upsamples it with depth
// awareness (shaders/common/upsample.glsl).
struct TranslucentLayer {
    ResourceHandle color;      // invalid: no layer this frame
    ResourceHandle depthUsed;  // R32F view depth per texel; invalid: full resolution
    ResourceHandle edges;      // mixed resolution: full-resolution texels of edgeRect, taken where alpha ≥ 0; invalid: none
    glm::ivec4 edgeRect{0};    // x, y (window pixels from the lower left), width, height
    float edgeThreshold = 0.2f;  // relative depth difference the upsampling treats as an edge
    glm::ivec4 coverRect{0};   // outside it the layer is empty (rgb 0, alpha 1); width 0: the whole viewport
};

// What an extension adds to the opaque pass's mesh shading (the media plugin: its light slices,
// through its GLSL host include): a define that shaders/opaque.frag tests to include it, the
// textures it samples (unit, resource) and a step that binds its uniform blocks.
struct MeshShadingInput {
    std::string define;
    std::vector<std::pair<GLuint, ResourceHandle>> textures;
    std::function<void()> bind;
};

// What the passes of one frame share while the graph is set up.
struct FrameContext {
    const FrameInput& input;
    RenderSettings settings;
    View view;
    assets::Aabb meshBounds;    // world
    assets::Aabb shadowBounds;  // world: meshes plus what extensions draw
    std::vector<std::vector<LightView>> shadowViews;  // per light
    ResourceHandle shadowMap;                         // depth array, one layer per shadow view (may be invalid)
    ResourceHandle sceneColor;                        // the output (RGBA32F): opaque radiance until compose
    ResourceHandle sceneDepth;                        // reversed-Z depth (D32F)
    std::vector<MeshShadingInput> meshShading;        // added by extensions before the opaque pass
    TranslucentLayer overlay;                         // set by an extension after it: composed over the opaque scene
    const FrameData* frameData = nullptr;
};

class RenderExtension {
public:
    virtual ~RenderExtension() = default;
    // World bounds of what the extension draws (shadow maps must cover it). Empty: nothing.
    virtual assets::Aabb bounds() const { return {}; }
    virtual void beforeOpaque(FrameGraph&, FrameContext&) {}
    virtual void afterOpaque(FrameGraph&, FrameContext&) {}
};

class ShadowPass;
class OpaquePass;
class ComposePass;

class SceneRenderer {
public:
    SceneRenderer();  // compiles the engine's programs; needs a current GL context
    ~SceneRenderer();
    SceneRenderer(const SceneRenderer&) = delete;
    SceneRenderer& operator=(const SceneRenderer&) = delete;

    // Renders one frame into output(). `timer` (optional) receives per-pass timings.
    void render(const FrameInput& input, const RenderSettings& settings, std::span<RenderExtension* const> extensions,
                PassTimer* timer = nullptr);

    const gpu::Texture& output() const { return output_; }
    assets::RgbImage readOutput() const;  // row 0 at the top
    std::vector<std::string> lastActivePasses() const { return lastPasses_; }

private:
    std::unique_ptr<ShadowPass> shadowPass_;
    std::unique_ptr<OpaquePass> opaquePass_;
    std::unique_ptr<ComposePass> composePass_;
    FrameData frameData_;
    TexturePool pool_;
    gpu::Texture output_;
    std::vector<std::string> lastPasses_;
    // The previous frame's completion. Buffers are rewritten every frame (no ring), and llvmpipe
    // does not order a buffer update after queued draws that read it, so a frame waits for the
    // last one before touching them.
    GLsync previousFrame_ = nullptr;
};

// World bounds of the instances' meshes.
assets::Aabb instanceBounds(const FrameInput& input);

}  // namespace nimbus::render
