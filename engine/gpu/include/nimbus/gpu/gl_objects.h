#pragma once
// RAII ownership of GL objects: one move-only handle type per object kind, deleting the name when it
// goes out of scope. Creation uses GL 4.5 direct state access (glCreate*), so a handle is valid
// without binding. All calls need the owning context to be current.
//
// Does not: track bindings or cache state; passes bind what they use.
#include <epoxy/gl.h>

#include <cstddef>
#include <utility>

namespace nimbus::gpu {

template <typename Traits>
class GlObject {
public:
    GlObject() = default;
    explicit GlObject(GLuint name) : name_(name) {}
    ~GlObject() { reset(); }
    GlObject(GlObject&& other) noexcept : name_(std::exchange(other.name_, 0)) {}
    GlObject& operator=(GlObject&& other) noexcept {
        if (this != &other) {
            reset();
            name_ = std::exchange(other.name_, 0);
        }
        return *this;
    }
    GlObject(const GlObject&) = delete;
    GlObject& operator=(const GlObject&) = delete;

    GLuint id() const { return name_; }
    explicit operator bool() const { return name_ != 0; }
    void reset() {
        if (name_ != 0) Traits::destroy(name_);
        name_ = 0;
    }

private:
    GLuint name_ = 0;
};

struct BufferTraits {
    static void destroy(GLuint n) { glDeleteBuffers(1, &n); }
};
struct VertexArrayTraits {
    static void destroy(GLuint n) { glDeleteVertexArrays(1, &n); }
};
struct FramebufferTraits {
    static void destroy(GLuint n) { glDeleteFramebuffers(1, &n); }
};
struct TextureTraits {
    static void destroy(GLuint n) { glDeleteTextures(1, &n); }
};
struct SamplerTraits {
    static void destroy(GLuint n) { glDeleteSamplers(1, &n); }
};
struct ShaderTraits {
    static void destroy(GLuint n) { glDeleteShader(n); }
};
struct ProgramTraits {
    static void destroy(GLuint n) { glDeleteProgram(n); }
};
struct QueryTraits {
    static void destroy(GLuint n) { glDeleteQueries(1, &n); }
};

using Buffer = GlObject<BufferTraits>;
using VertexArray = GlObject<VertexArrayTraits>;
using Framebuffer = GlObject<FramebufferTraits>;
using Sampler = GlObject<SamplerTraits>;
using Shader = GlObject<ShaderTraits>;
using Program = GlObject<ProgramTraits>;
using Query = GlObject<QueryTraits>;

// Immutable-storage buffer (glNamedBufferStorage). `flags` e.g. GL_DYNAMIC_STORAGE_BIT for updates.
Buffer createBuffer(std::size_t bytes, const void* data = nullptr, GLbitfield flags = GL_DYNAMIC_STORAGE_BIT);
VertexArray createVertexArray();
Framebuffer createFramebuffer();
Sampler createSampler(GLenum minFilter, GLenum magFilter, GLenum wrap);

// What a texture is. Zero fields take the default noted.
struct TextureDesc {
    GLenum target = GL_TEXTURE_2D;  // or GL_TEXTURE_2D_ARRAY, GL_TEXTURE_3D
    GLenum format = GL_RGBA32F;     // sized internal format
    int width = 0;
    int height = 0;
    int depth = 0;    // layers for arrays, depth for 3D; 0 means 1
    int levels = 0;   // 0 means 1
    bool operator==(const TextureDesc&) const = default;
};

class Texture {
public:
    Texture() = default;
    explicit Texture(const TextureDesc& desc);  // allocates immutable storage with default sampling state
    // A texture someone else owns (a host's depth buffer), described by `desc`; never deleted here.
    static Texture borrow(GLuint name, const TextureDesc& desc);
    GLuint id() const { return handle_ ? handle_.id() : borrowed_; }
    const TextureDesc& desc() const { return desc_; }
    explicit operator bool() const { return id() != 0; }

private:
    GlObject<TextureTraits> handle_;
    GLuint borrowed_ = 0;
    TextureDesc desc_;
};

bool isDepthFormat(GLenum format);

}  // namespace nimbus::gpu
