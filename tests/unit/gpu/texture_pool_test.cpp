// TexturePool (render/texture_pool.h), the GL ResourceAllocator: textures are reused by
// description, never handed out twice at once, and freed after a few idle frames.
#include "nimbus/gpu/texture_pool.h"

#include <gtest/gtest.h>

#include <memory>

#include "nimbus/gpu/context.h"

namespace nimbus::gpu {
namespace {

class TexturePoolTest : public ::testing::Test {
protected:
    static void SetUpTestSuite() { context_ = gpu::Context::create(); }
    static void TearDownTestSuite() { context_.reset(); }
    void SetUp() override { context_->makeCurrent(); }
    void TearDown() override { EXPECT_EQ(context_->takeGlErrors().count, 0u); }

private:
    static inline std::unique_ptr<gpu::Context> context_;
};

const TextureDesc kColor{GL_TEXTURE_2D, GL_RGBA32F, 16, 8, 1, 1};

TEST_F(TexturePoolTest, ReusesAReleasedTextureOfTheSameDescription) {
    TexturePool pool;
    const Texture* a = pool.acquire(kColor);
    ASSERT_NE(a, nullptr);
    EXPECT_EQ(glIsTexture(a->id()), GL_TRUE);
    EXPECT_EQ(a->desc(), kColor);
    pool.release(a);
    EXPECT_EQ(pool.acquire(kColor), a);
    EXPECT_EQ(pool.size(), 1u);
}

TEST_F(TexturePoolTest, NeverHandsOutATextureInUse) {
    TexturePool pool;
    const Texture* a = pool.acquire(kColor);
    const Texture* b = pool.acquire(kColor);
    EXPECT_NE(a, b);
    EXPECT_NE(a->id(), b->id());
    EXPECT_EQ(pool.size(), 2u);
}

TEST_F(TexturePoolTest, DifferentDescriptionsGetDifferentTextures) {
    TexturePool pool;
    const Texture* a = pool.acquire(kColor);
    pool.release(a);
    TextureDesc depth = kColor;
    depth.format = GL_DEPTH_COMPONENT32F;
    TextureDesc bigger = kColor;
    bigger.width = 32;
    EXPECT_NE(pool.acquire(depth), a);
    EXPECT_NE(pool.acquire(bigger), a);
    EXPECT_EQ(pool.size(), 3u);
}

TEST_F(TexturePoolTest, ZeroDepthAndLevelsMeanOne) {
    TexturePool pool;
    const Texture* a = pool.acquire({GL_TEXTURE_2D, GL_RGBA32F, 16, 8, 0, 0});
    pool.release(a);
    EXPECT_EQ(pool.acquire(kColor), a);
}

TEST_F(TexturePoolTest, FreesTexturesIdleForMoreThanThreeFrames) {
    TexturePool pool;
    const Texture* idle = pool.acquire(kColor);
    const GLuint idleName = idle->id();
    TextureDesc other = kColor;
    other.height = 4;
    const Texture* busy = pool.acquire(other);  // held across frames: never freed
    pool.release(idle);
    for (int frame = 1; frame <= 3; ++frame) {
        pool.endFrame();
        EXPECT_EQ(pool.size(), 2u) << "still pooled after " << frame << " idle frame(s)";
    }
    pool.endFrame();
    EXPECT_EQ(pool.size(), 1u);
    EXPECT_EQ(glIsTexture(idleName), GL_FALSE);
    EXPECT_EQ(glIsTexture(busy->id()), GL_TRUE);
}

TEST_F(TexturePoolTest, UseResetsTheIdleCount) {
    TexturePool pool;
    const Texture* a = pool.acquire(kColor);
    pool.release(a);
    pool.endFrame();
    pool.endFrame();
    pool.release(pool.acquire(kColor));  // used again this frame
    pool.endFrame();
    pool.endFrame();
    pool.endFrame();
    EXPECT_EQ(pool.size(), 1u);
}

}  // namespace
}  // namespace nimbus::gpu
