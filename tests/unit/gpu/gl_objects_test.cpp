// RAII GL objects (gpu/gl_objects.h): names exist while a handle owns them, are deleted when it
// goes away, and move with the handle.
#include "nimbus/gpu/gl_objects.h"

#include <gtest/gtest.h>

#include <array>
#include <utility>
#include <vector>

#include "gl_test_context.h"

namespace nimbus::gpu {
namespace {

class GlObjects : public test::GlTest {};

TEST_F(GlObjects, BufferNameIsReleasedOnDestruction) {
    GLuint name = 0;
    {
        const std::array<float, 4> data = {1, 2, 3, 4};
        const Buffer buffer = createBuffer(sizeof data, data.data(), 0);
        name = buffer.id();
        ASSERT_NE(name, 0u);
        EXPECT_EQ(glIsBuffer(name), GL_TRUE);
        std::array<float, 4> back{};
        glGetNamedBufferSubData(name, 0, sizeof back, back.data());
        EXPECT_EQ(back, data);
    }
    EXPECT_EQ(glIsBuffer(name), GL_FALSE);
    EXPECT_EQ(context().takeGlErrors().count, 0u);
}

TEST_F(GlObjects, EmptyBuffersStillGetStorage) {
    const Buffer buffer = createBuffer(0);
    GLint64 size = 0;
    glGetNamedBufferParameteri64v(buffer.id(), GL_BUFFER_SIZE, &size);
    EXPECT_EQ(size, 1);
    EXPECT_EQ(context().takeGlErrors().count, 0u);
}

TEST_F(GlObjects, MovingTransfersOwnership) {
    Buffer a = createBuffer(16);
    const GLuint name = a.id();
    Buffer b = std::move(a);
    EXPECT_EQ(a.id(), 0u);  // NOLINT(bugprone-use-after-move): the moved-from state is the point
    EXPECT_FALSE(a);
    EXPECT_EQ(b.id(), name);
    EXPECT_EQ(glIsBuffer(name), GL_TRUE);

    Buffer c = createBuffer(16);
    const GLuint replaced = c.id();
    c = std::move(b);  // c's old name is deleted, b's name now lives in c
    EXPECT_EQ(glIsBuffer(replaced), GL_FALSE);
    EXPECT_EQ(c.id(), name);
    EXPECT_EQ(glIsBuffer(name), GL_TRUE);
    c.reset();
    EXPECT_EQ(glIsBuffer(name), GL_FALSE);
    EXPECT_FALSE(c);
}

TEST_F(GlObjects, EveryKindReleasesItsName) {
    GLuint vao = 0, fbo = 0, sampler = 0, texture = 0, program = 0, shader = 0, query = 0;
    {
        const VertexArray v = createVertexArray();
        const Framebuffer f = createFramebuffer();
        const Sampler s = createSampler(GL_LINEAR, GL_NEAREST, GL_REPEAT);
        const Texture t({GL_TEXTURE_2D, GL_RGBA32F, 8, 4, 0, 0});
        const Program p(glCreateProgram());
        const Shader sh(glCreateShader(GL_FRAGMENT_SHADER));
        GLuint q = 0;
        glCreateQueries(GL_TIME_ELAPSED, 1, &q);
        const Query query_(q);
        vao = v.id(), fbo = f.id(), sampler = s.id(), texture = t.id(), program = p.id(), shader = sh.id(), query = q;
        EXPECT_EQ(glIsVertexArray(vao), GL_TRUE);
        EXPECT_EQ(glIsFramebuffer(fbo), GL_TRUE);
        EXPECT_EQ(glIsSampler(sampler), GL_TRUE);
        EXPECT_EQ(glIsTexture(texture), GL_TRUE);
        EXPECT_EQ(glIsProgram(program), GL_TRUE);
        EXPECT_EQ(glIsShader(shader), GL_TRUE);
        EXPECT_EQ(glIsQuery(query), GL_TRUE);
    }
    EXPECT_EQ(glIsVertexArray(vao), GL_FALSE);
    EXPECT_EQ(glIsFramebuffer(fbo), GL_FALSE);
    EXPECT_EQ(glIsSampler(sampler), GL_FALSE);
    EXPECT_EQ(glIsTexture(texture), GL_FALSE);
    EXPECT_EQ(glIsProgram(program), GL_FALSE);
    EXPECT_EQ(glIsShader(shader), GL_FALSE);
    EXPECT_EQ(glIsQuery(query), GL_FALSE);
    EXPECT_EQ(context().takeGlErrors().count, 0u);
}

TEST_F(GlObjects, TextureDescriptionDefaultsAndStorage) {
    const Texture t({GL_TEXTURE_2D_ARRAY, GL_DEPTH_COMPONENT32F, 16, 8, 3, 0});
    EXPECT_EQ(t.desc().depth, 3);
    EXPECT_EQ(t.desc().levels, 1);  // 0 means 1
    GLint width = 0, height = 0, layers = 0, format = 0, minFilter = 0;
    glGetTextureLevelParameteriv(t.id(), 0, GL_TEXTURE_WIDTH, &width);
    glGetTextureLevelParameteriv(t.id(), 0, GL_TEXTURE_HEIGHT, &height);
    glGetTextureLevelParameteriv(t.id(), 0, GL_TEXTURE_DEPTH, &layers);
    glGetTextureLevelParameteriv(t.id(), 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
    glGetTextureParameteriv(t.id(), GL_TEXTURE_MIN_FILTER, &minFilter);
    EXPECT_EQ(width, 16);
    EXPECT_EQ(height, 8);
    EXPECT_EQ(layers, 3);
    EXPECT_EQ(format, GL_DEPTH_COMPONENT32F);
    EXPECT_EQ(minFilter, GL_NEAREST) << "depth textures are read texel-exact";
    EXPECT_TRUE(isDepthFormat(GL_DEPTH_COMPONENT32F));
    EXPECT_FALSE(isDepthFormat(GL_RGBA32F));
    EXPECT_EQ(context().takeGlErrors().count, 0u);
}

TEST_F(GlObjects, ABorrowedTextureIsNeverDeleted) {
    GLuint name = 0;
    glCreateTextures(GL_TEXTURE_2D, 1, &name);
    glTextureStorage2D(name, 1, GL_DEPTH_COMPONENT32F, 8, 4);
    {
        const Texture borrowed = Texture::borrow(name, {GL_TEXTURE_2D, GL_DEPTH_COMPONENT32F, 8, 4, 0, 0});
        EXPECT_EQ(borrowed.id(), name);
        EXPECT_TRUE(static_cast<bool>(borrowed));
        EXPECT_EQ(borrowed.desc().depth, 1) << "zero fields take their defaults, as for owned textures";
    }
    EXPECT_TRUE(glIsTexture(name)) << "the host still owns it";
    glDeleteTextures(1, &name);
    EXPECT_EQ(context().takeGlErrors().count, 0u);
}

TEST_F(GlObjects, ManyHandlesInAVectorReleaseAll) {
    std::vector<GLuint> names;
    {
        std::vector<Buffer> buffers;
        for (int i = 0; i < 64; ++i) {
            buffers.push_back(createBuffer(4));  // reallocation moves handles; none may be deleted early
            names.push_back(buffers.back().id());
        }
        for (const GLuint n : names) EXPECT_EQ(glIsBuffer(n), GL_TRUE);
    }
    for (const GLuint n : names) EXPECT_EQ(glIsBuffer(n), GL_FALSE);
}

}  // namespace
}  // namespace nimbus::gpu
