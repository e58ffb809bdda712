#include "nimbus/render/gpu_scene.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace nimbus::render {
namespace {

constexpr int kFloatsPerVertex = 10;

GpuPrimitive upload(const assets::Primitive& p) {
    std::vector<float> interleaved(p.positions.size() * kFloatsPerVertex, 0.0f);
    for (std::size_t i = 0; i < p.positions.size(); ++i) {
        float* v = &interleaved[i * kFloatsPerVertex];
        v[0] = p.positions[i].x, v[1] = p.positions[i].y, v[2] = p.positions[i].z;
        v[3] = p.normals[i].x, v[4] = p.normals[i].y, v[5] = p.normals[i].z;
        if (!p.texcoords0.empty()) v[6] = p.texcoords0[i].x, v[7] = p.texcoords0[i].y;
        if (!p.texcoords1.empty()) v[8] = p.texcoords1[i].x, v[9] = p.texcoords1[i].y;
    }
    GpuPrimitive g;
    g.vertices = gpu::createBuffer(interleaved.size() * sizeof(float), interleaved.data(), 0);
    g.indices = gpu::createBuffer(p.indices.size() * sizeof(std::uint32_t), p.indices.data(), 0);
    g.indexCount = static_cast<GLsizei>(p.indices.size());
    g.material = p.material;
    g.vertexArray = gpu::createVertexArray();
    const GLuint vao = g.vertexArray.id();
    glVertexArrayVertexBuffer(vao, 0, g.vertices.id(), 0, kFloatsPerVertex * sizeof(float));
    glVertexArrayElementBuffer(vao, g.indices.id());
    const int sizes[] = {3, 3, 2, 2};
    GLuint offset = 0;
    for (GLuint attribute = 0; attribute < 4; ++attribute) {
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

GpuTexture uploadTexture(const assets::Texture& t, const assets::Image& image) {
    const int levels = t.mipmaps ? 1 + static_cast<int>(std::floor(std::log2(std::max(image.width, image.height)))) : 1;
    GpuTexture g;
    // baseColor textures are sRGB-encoded: the GPU decodes per texel before filtering, like the reference.
    g.texture = gpu::Texture({GL_TEXTURE_2D, GL_SRGB8_ALPHA8, image.width, image.height, 1, levels});
    // glTF images have row 0 at the top and UV (0,0) at the top-left: upload rows as they are and
    // let v index rows downwards, which is what GL does with t = v when row 0 is uploaded first.
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTextureSubImage2D(g.texture.id(), 0, 0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba8.data());
    if (levels > 1) glGenerateTextureMipmap(g.texture.id());
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
    for (const auto& t : scene.textures) textures_.push_back(uploadTexture(t, scene.images.at(static_cast<std::size_t>(t.image))));
    for (const auto& m : scene.materials)
        materials_.push_back({m.baseColorFactor, m.baseColorTexture, m.baseColorTexCoord, m.doubleSided});
}

const GpuMaterial& GpuScene::material(int index) const {
    if (index < 0) return defaultMaterial_;
    return materials_.at(static_cast<std::size_t>(index));
}

}  // namespace nimbus::render
