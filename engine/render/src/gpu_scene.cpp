#include "nimbus/render/gpu_scene.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace nimbus::render {
namespace {

constexpr int kFloatsPerVertex = 14;

GpuPrimitive upload(const assets::Primitive& p) {
    std::vector<float> interleaved(p.positions.size() * kFloatsPerVertex, 0.0f);
    for (std::size_t i = 0; i < p.positions.size(); ++i) {
        float* v = &interleaved[i * kFloatsPerVertex];
        v[0] = p.positions[i].x, v[1] = p.positions[i].y, v[2] = p.positions[i].z;
        v[3] = p.normals[i].x, v[4] = p.normals[i].y, v[5] = p.normals[i].z;
        if (!p.texcoords0.empty()) v[6] = p.texcoords0[i].x, v[7] = p.texcoords0[i].y;
        if (!p.texcoords1.empty()) v[8] = p.texcoords1[i].x, v[9] = p.texcoords1[i].y;
        const glm::vec4 color = p.colors0.empty() ? glm::vec4(1.0f) : p.colors0[i];
        v[10] = color.r, v[11] = color.g, v[12] = color.b, v[13] = color.a;
    }
    GpuPrimitive g;
    g.vertices = gpu::createBuffer(interleaved.size() * sizeof(float), interleaved.data(), 0);
    g.indices = gpu::createBuffer(p.indices.size() * sizeof(std::uint32_t), p.indices.data(), 0);
    g.indexCount = static_cast<GLsizei>(p.indices.size());
    g.material = p.material;
    g.vertexColors = !p.colors0.empty();
    g.vertexArray = gpu::createVertexArray();
    const GLuint vao = g.vertexArray.id();
    glVertexArrayVertexBuffer(vao, 0, g.vertices.id(), 0, kFloatsPerVertex * sizeof(float));
    glVertexArrayElementBuffer(vao, g.indices.id());
    const int sizes[] = {3, 3, 2, 2, 4};
    GLuint offset = 0;
    for (GLuint attribute = 0; attribute < 5; ++attribute) {
        glEnableVertexArrayAttrib(vao, attribute);
        glVertexArrayAttribFormat(vao, attribute, sizes[attribute], GL_FLOAT, GL_FALSE, offset * sizeof(float));
        glVertexArrayAttribBinding(vao, attribute, 0);
        offset += static_cast<GLuint>(sizes[attribute]);
    }
    return g;
}

GLenum glWrap(assets::Wrap w) {
    switch (w) {
        case assets::Wrap::ClampToEdge: return GL_CLAMP_TO_EDGE;
        case assets::Wrap::MirroredRepeat: return GL_MIRRORED_REPEAT;
        case assets::Wrap::Repeat: break;
    }
    return GL_REPEAT;
}

gpu::Texture uploadImage(const assets::Image& image, int levels, GLenum format) {
    gpu::Texture texture({GL_TEXTURE_2D, format, image.width, image.height, 1, levels});
    // glTF images have row 0 at the top and UV (0,0) at the top-left: upload rows as they are and
    // let v index rows downwards, which is what GL does with t = v when row 0 is uploaded first.
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTextureSubImage2D(texture.id(), 0, 0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba8.data());
    if (levels > 1) glGenerateTextureMipmap(texture.id());
    return texture;
}

GpuTexture uploadTexture(const assets::Texture& t, const assets::Image& image, bool srgb, bool linear) {
    const int levels = t.mipmaps ? 1 + static_cast<int>(std::floor(std::log2(std::max(image.width, image.height)))) : 1;
    GpuTexture g;
    // sRGB-encoded colours: the GPU decodes per texel before filtering, like the reference.
    if (srgb) g.srgb = uploadImage(image, levels, GL_SRGB8_ALPHA8);
    if (linear) g.linear = uploadImage(image, levels, GL_RGBA8);
    const GLenum mag = t.magFilter == assets::Filter::Nearest ? GL_NEAREST : GL_LINEAR;
    GLenum min = t.minFilter == assets::Filter::Nearest ? GL_NEAREST : GL_LINEAR;
    if (levels > 1) min = t.minFilter == assets::Filter::Nearest ? GL_NEAREST_MIPMAP_LINEAR : GL_LINEAR_MIPMAP_LINEAR;
    g.sampler = gpu::createSampler(min, mag, GL_REPEAT);
    glSamplerParameteri(g.sampler.id(), GL_TEXTURE_WRAP_S, static_cast<GLint>(glWrap(t.wrapS)));
    glSamplerParameteri(g.sampler.id(), GL_TEXTURE_WRAP_T, static_cast<GLint>(glWrap(t.wrapT)));
    return g;
}

}  // namespace

GpuScene::GpuScene(const assets::Scene& scene) {
    meshes_.reserve(scene.meshes.size());
    for (const auto& mesh : scene.meshes) {
        std::vector<GpuPrimitive> primitives;
        glm::vec3 lo(std::numeric_limits<float>::infinity()), hi(-std::numeric_limits<float>::infinity());
        for (const auto& p : mesh.primitives) {
            if (p.indices.empty()) continue;
            primitives.push_back(upload(p));
            lo = glm::min(lo, p.boundsMin);
            hi = glm::max(hi, p.boundsMax);
        }
        bounds_.emplace_back(lo, hi);
        meshes_.push_back(std::move(primitives));
    }
    // How each texture is read decides its GL format(s).
    std::vector<bool> srgb(scene.textures.size(), false), linear(scene.textures.size(), false);
    for (const auto& m : scene.materials) {
        if (m.baseColorTexture.present()) srgb[static_cast<std::size_t>(m.baseColorTexture.texture)] = true;
        if (m.emissiveTexture.present()) srgb[static_cast<std::size_t>(m.emissiveTexture.texture)] = true;
        if (m.metallicRoughnessTexture.present()) linear[static_cast<std::size_t>(m.metallicRoughnessTexture.texture)] = true;
    }
    for (std::size_t i = 0; i < scene.textures.size(); ++i) {
        const assets::Texture& t = scene.textures[i];
        textures_.push_back(uploadTexture(t, scene.images.at(static_cast<std::size_t>(t.image)), srgb[i], linear[i]));
    }
    for (const auto& m : scene.materials) materials_.push_back({m});
}

const GpuMaterial& GpuScene::material(int index) const {
    if (index < 0) return defaultMaterial_;
    return materials_.at(static_cast<std::size_t>(index));
}

}  // namespace nimbus::render
