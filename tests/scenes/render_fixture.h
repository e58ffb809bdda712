#pragma once
// Test helper: one headless GL context per test suite, and a frame rendered the way `sandbox
// render` renders it (App + RenderPlugin, scene spawned and simulated, Prepare/Render/Present).
#include <gtest/gtest.h>

#include <memory>

#include "nimbus/assets/image_io.h"
#include "nimbus/base/settings.h"
#include "nimbus/ecs/app.h"
#include "nimbus/gpu/context.h"
#include "nimbus/render/render_plugin.h"
#include "nimbus/render/view.h"
#include "nimbus/scene/scene_plugin.h"

namespace nimbus::test {

class GlSceneTest : public ::testing::Test {
protected:
    static void SetUpTestSuite() { context_ = gpu::Context::create(); }
    static void TearDownTestSuite() { context_.reset(); }
    void SetUp() override {
        context_->makeCurrent();
        (void)context_->takeGlErrors();
    }
    static gpu::Context& context() { return *context_; }

private:
    static inline std::unique_ptr<gpu::Context> context_;
};

struct AppFrame {
    assets::RgbImage image;
    assets::ResolvedCamera camera;            // what the renderer used
    std::vector<render::MeshInstance> instances;
    render::View view;                        // makeView of that camera at the image size
};

// Renders `scene` at `time` through the ECS like the sandbox does (without the media plugin).
inline AppFrame renderThroughApp(std::shared_ptr<const assets::Scene> scene, int width, int height, double time = 0.0) {
    ecs::App app;
    app.insertResource<Settings>();
    app.addPlugin<render::RenderPlugin>();
    scene::spawnScene(app.world(), scene);
    scene::simulateTo(app, time);
    auto& request = app.resource<render::RenderRequest>();
    request.enabled = true;
    request.settings.width = width;
    request.settings.height = height;
    app.redraw();
    const auto& state = app.resource<render::RendererState>();
    AppFrame frame;
    frame.image = state.renderer->readOutput();
    frame.camera = state.lastInput.camera;
    frame.instances = state.lastInput.instances;
    frame.view = render::makeView(frame.camera, width, height);
    return frame;
}

}  // namespace nimbus::test
