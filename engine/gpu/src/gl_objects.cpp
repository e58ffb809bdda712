#include "nimbus/gpu/gl_objects.h"

#include <algorithm>

namespace nimbus::gpu {

Buffer createBuffer(std::size_t bytes, const void* data, GLbitfield flags) {
    GLuint name = 0;
    glCreateBuffers(1, &name);
    // Zero-sized storage is an error in GL; keep one byte so empty scenes still bind something.
    glNamedBufferStorage(name, static_cast<GLsizeiptr>(std::max<std::size_t>(bytes, 1)), bytes ? data : nullptr, flags);
    return Buffer(name);
}

VertexArray createVertexArray() {
    GLuint name = 0;
    glCreateVertexArrays(1, &name);
    return VertexArray(name);
}

Framebuffer createFramebuffer() {
    GLuint name = 0;
    glCreateFramebuffers(1, &name);
    return Framebuffer(name);
}

Sampler createSampler(GLenum minFilter, GLenum magFilter, GLenum wrap) {
    GLuint name = 0;
    glCreateSamplers(1, &name);
    glSamplerParameteri(name, GL_TEXTURE_MIN_FILTER, static_cast<GLint>(minFilter));
    glSamplerParameteri(name, GL_TEXTURE_MAG_FILTER, static_cast<GLint>(magFilter));
    glSamplerParameteri(name, GL_TEXTURE_WRAP_S, static_cast<GLint>(wrap));
    glSamplerParameteri(name, GL_TEXTURE_WRAP_T, static_cast<GLint>(wrap));
    glSamplerParameteri(name, GL_TEXTURE_WRAP_R, static_cast<GLint>(wrap));
    return Sampler(name);
}

bool isDepthFormat(GLenum format) {
    return format == GL_DEPTH_COMPONENT32F || format == GL_DEPTH_COMPONENT24 || format == GL_DEPTH_COMPONENT16 ||
           format == GL_DEPTH32F_STENCIL8 || format == GL_DEPTH24_STENCIL8;
}

namespace {

// Zero depth and levels mean 1.
TextureDesc withDefaults(TextureDesc desc) {
    desc.depth = std::max(desc.depth, 1);
    desc.levels = std::max(desc.levels, 1);
    return desc;
}

}  // namespace

Texture::Texture(const TextureDesc& desc) : desc_(withDefaults(desc)) {
    GLuint name = 0;
    glCreateTextures(desc_.target, 1, &name);
    handle_ = GlObject<TextureTraits>(name);
    switch (desc_.target) {
        case GL_TEXTURE_2D_ARRAY:
        case GL_TEXTURE_3D:
            glTextureStorage3D(name, desc_.levels, desc_.format, desc_.width, desc_.height, desc_.depth);
            break;
        default:
            glTextureStorage2D(name, desc_.levels, desc_.format, desc_.width, desc_.height);
            break;
    }
    // Render targets are read texel-exact unless a pass binds its own sampler.
    const GLint filter = desc_.levels > 1 ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR;
    glTextureParameteri(name, GL_TEXTURE_MIN_FILTER, isDepthFormat(desc_.format) ? GL_NEAREST : filter);
    glTextureParameteri(name, GL_TEXTURE_MAG_FILTER, isDepthFormat(desc_.format) ? GL_NEAREST : GL_LINEAR);
    glTextureParameteri(name, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(name, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTextureParameteri(name, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
}

Texture Texture::borrow(GLuint name, const TextureDesc& desc) {
    Texture t;
    t.borrowed_ = name;
    t.desc_ = withDefaults(desc);
    return t;
}

}  // namespace nimbus::gpu
