// The headless context (gpu/context.h): GL 4.5 core through EGL, with the state every pass assumes.
#include "nimbus/gpu/context.h"

#include <gtest/gtest.h>

#include <epoxy/gl.h>

namespace nimbus::gpu {
namespace {

TEST(HeadlessContext, IsGl45CoreWithZeroToOneClipDepth) {
    auto context = Context::create();
    ASSERT_NE(context, nullptr);
    EXPECT_GE(epoxy_gl_version(), 45);
    EXPECT_FALSE(context->renderer().empty());
    EXPECT_NE(context->renderer(), "unknown");
    EXPECT_NE(context->version().find("4."), std::string::npos) << context->version();
    GLint profile = 0;
    glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
    EXPECT_TRUE(profile & GL_CONTEXT_CORE_PROFILE_BIT);
    // Reversed Z needs [0, 1] clip depth (glClipControl), set once at creation.
    GLint depthMode = 0;
    glGetIntegerv(GL_CLIP_DEPTH_MODE, &depthMode);
    EXPECT_EQ(depthMode, GL_ZERO_TO_ONE);
    EXPECT_EQ(glIsEnabled(GL_TEXTURE_CUBE_MAP_SEAMLESS), GL_TRUE);
}

TEST(HeadlessContext, HasNoWindow) {
    auto context = Context::create();
    int w = -1, h = -1;
    context->framebufferSize(w, h);
    EXPECT_EQ(w, 0);
    EXPECT_EQ(h, 0);
    EXPECT_EQ(context->nativeWindow(), nullptr);
    EXPECT_FALSE(context->shouldClose());
    context->swapBuffers();  // harmless no-ops
    context->pollEvents();
    EXPECT_EQ(context->takeGlErrors().count, 0u);
}

TEST(HeadlessContext, CanBeMadeAgainAfterOneIsDestroyed) {
    // Sandbox commands and tests create and destroy contexts in sequence within one process.
    for (int i = 0; i < 3; ++i) {
        auto context = Context::create();
        GLuint buffer = 0;
        glCreateBuffers(1, &buffer);
        EXPECT_EQ(glIsBuffer(buffer), GL_TRUE);
        glDeleteBuffers(1, &buffer);
        EXPECT_EQ(context->takeGlErrors().count, 0u);
    }
}

}  // namespace
}  // namespace nimbus::gpu
