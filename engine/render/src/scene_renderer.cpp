#include "nimbus/render/scene_renderer.h"

#include <algorithm>
#include <cmath>

#include "passes.h"

namespace nimbus::render {
namespace {

RenderSettings withDefaults(RenderSettings s) {
    if (s.width <= 0) s.width = 1280;
    if (s.height <= 0) s.height = 720;
    if (s.shadowMapSize <= 0) s.shadowMapSize = 2048;
    if (s.pcfRadius < 0) s.pcfRadius = 1;
    return s;
}

}  // namespace

int pointShadowSize(const RenderSettings& settings) {
    const float scale = settings.pointShadowScale > 0.0f ? std::min(settings.pointShadowScale, 1.0f) : 1.0f;
    return std::max(static_cast<int>(std::lround(static_cast<float>(settings.shadowMapSize) * scale)), 1);
}

assets::Aabb instanceBounds(const FrameInput& input) {
    assets::Aabb bounds;
    for (const auto& instance : input.instances) {
        const auto& [lo, hi] = input.gpuScene->localBounds(instance.mesh);
        if (lo.x > hi.x) continue;  // mesh without triangles
        for (int i = 0; i < 8; ++i) {
            const glm::dvec3 corner(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z);
            bounds.extend(glm::dvec3(instance.world * glm::dvec4(corner, 1.0)));
        }
    }
    return bounds;
}

SceneRenderer::SceneRenderer()
    : shadowPass_(std::make_unique<ShadowPass>()),
      opaquePass_(std::make_unique<OpaquePass>()),
      composePass_(std::make_unique<ComposePass>()) {}

SceneRenderer::~SceneRenderer() {
    if (previousFrame_ != nullptr) glDeleteSync(previousFrame_);
}

void SceneRenderer::render(const FrameInput& input, const RenderSettings& requested,
                           std::span<RenderExtension* const> extensions, PassTimer* timer) {
    if (previousFrame_ != nullptr) {
        glClientWaitSync(previousFrame_, GL_SYNC_FLUSH_COMMANDS_BIT, GLuint64{10'000'000'000});  // 10 s: a frame, not a hang
        glDeleteSync(previousFrame_);
        previousFrame_ = nullptr;
    }
    const RenderSettings settings = withDefaults(requested);
    if (!output_ || output_.desc().width != settings.width || output_.desc().height != settings.height)
        output_ = gpu::Texture({GL_TEXTURE_2D, GL_RGBA32F, settings.width, settings.height, 1, 1});

    FrameContext context{input, settings, makeView(input.camera, settings.width, settings.height)};
    context.frameData = &frameData_;
    context.meshBounds = instanceBounds(input);
    context.shadowBounds = context.meshBounds;
    for (auto* extension : extensions) context.shadowBounds.extend(extension->bounds());
    for (const auto& light : input.lights) context.shadowViews.push_back(makeLightViews(light, context.shadowBounds, context.view.origin));

    FrameGraph graph(pool_);
    shadowPass_->add(graph, context);
    for (auto* extension : extensions) extension->beforeOpaque(graph, context);
    opaquePass_->add(graph, context, *shadowPass_, output_);
    for (auto* extension : extensions) extension->afterOpaque(graph, context);
    composePass_->add(graph, context);

    // Everything the shaders read per frame is known once setup is done.
    frameData_.update(context.view, input.environment, input.lights, context.shadowViews, settings.shadowMapSize,
                      pointShadowSize(settings), settings.pcfRadius);
    graph.compile();
    graph.execute(timer);
    lastPasses_ = graph.activePasses();
    pool_.endFrame();
    previousFrame_ = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
}

assets::RgbImage SceneRenderer::readOutput() const {
    const int w = output_.desc().width, h = output_.desc().height;
    std::vector<float> rgba(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTextureImage(output_.id(), 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(rgba.size() * sizeof(float)), rgba.data());
    assets::RgbImage image(w, h);
    for (int y = 0; y < h; ++y) {
        const int source = h - 1 - y;  // GL rows start at the bottom
        for (int x = 0; x < w; ++x) {
            const float* p = &rgba[(static_cast<std::size_t>(source) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x)) * 4];
            image.set(x, y, {p[0], p[1], p[2]});
        }
    }
    return image;
}

}  // namespace nimbus::render
