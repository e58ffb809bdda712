// The window context (gpu/context.h, glfw_context.cpp): what the editor draws into. Runs under
// xvfb-run (tests/unit/gpu/CMakeLists.txt), so it needs an X server but no GPU.
#include "nimbus/gpu/context.h"

#include <gtest/gtest.h>

#include <epoxy/gl.h>

#include <array>
#include <cstdint>
#include <memory>

namespace nimbus::gpu {
namespace {

// One window for the suite: closing GLFW's last window drops the X connection, and Xvfb resets when
// its last client leaves (xvfb-run also passes -noreset, see CMakeLists.txt).
class WindowContext : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        context_ = Context::create({.kind = ContextKind::Window, .width = 96, .height = 64, .title = "nimbus test"});
    }
    static void TearDownTestSuite() { context_.reset(); }
    static inline std::unique_ptr<Context> context_;
};

TEST_F(WindowContext, IsGl45CoreWithAWindowOfTheRequestedSize) {
    Context* context = context_.get();
    ASSERT_NE(context, nullptr);
    EXPECT_NE(context->nativeWindow(), nullptr);
    EXPECT_GE(epoxy_gl_version(), 45);
    GLint profile = 0;
    glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
    EXPECT_TRUE(profile & GL_CONTEXT_CORE_PROFILE_BIT);
    // The same clip convention as the headless context: reversed Z relies on it in every pass.
    GLint depthMode = 0;
    glGetIntegerv(GL_CLIP_DEPTH_MODE, &depthMode);
    EXPECT_EQ(depthMode, GL_ZERO_TO_ONE);
    int w = 0, h = 0;
    context->framebufferSize(w, h);
    EXPECT_EQ(w, 96);
    EXPECT_EQ(h, 64);
    EXPECT_FALSE(context->shouldClose());
}

TEST_F(WindowContext, DrawsIntoTheWindowsBackBufferAndPresentsIt) {
    Context* context = context_.get();
    ASSERT_NE(context, nullptr);
    context->makeCurrent();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, 96, 64);
    glClearColor(0.25f, 0.5f, 1.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    std::array<std::uint8_t, 4> pixel{};
    glReadBuffer(GL_BACK);
    glReadPixels(16, 16, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixel.data());
    EXPECT_NEAR(pixel[0], 64, 1);
    EXPECT_NEAR(pixel[1], 128, 1);
    EXPECT_EQ(pixel[2], 255);
    context->swapBuffers();
    context->pollEvents();
    EXPECT_FALSE(context->shouldClose());
    EXPECT_EQ(context->takeGlErrors().count, 0u);
}

}  // namespace
}  // namespace nimbus::gpu
