#include "gpu_meshes.h"

namespace mini {
namespace gpu = nimbus::gpu;
namespace {

// Two tightly packed vec3 streams: the shadow pass reads only the first.
GpuPrimitive upload(const Primitive& p) {
    GpuPrimitive g;
    g.positions = gpu::createBuffer(p.positions.size() * sizeof(glm::vec3), p.positions.data(), 0);
    g.normals = gpu::createBuffer(p.normals.size() * sizeof(glm::vec3), p.normals.data(), 0);
    g.indices = gpu::createBuffer(p.indices.size() * sizeof(std::uint32_t), p.indices.data(), 0);
    g.indexCount = static_cast<GLsizei>(p.indices.size());
    g.material = p.material;
    g.vertexArray = gpu::createVertexArray();
    const GLuint vao = g.vertexArray.id();
    const GLuint buffers[] = {g.positions.id(), g.normals.id()};
    for (GLuint attribute = 0; attribute < 2; ++attribute) {
        glVertexArrayVertexBuffer(vao, attribute, buffers[attribute], 0, sizeof(glm::vec3));
        glEnableVertexArrayAttrib(vao, attribute);
        glVertexArrayAttribFormat(vao, attribute, 3, GL_FLOAT, GL_FALSE, 0);
        glVertexArrayAttribBinding(vao, attribute, attribute);
    }
    glVertexArrayElementBuffer(vao, g.indices.id());
    return g;
}

}  // namespace

GpuMeshes::GpuMeshes(const Scene& scene) : materials_(scene.materials) {
    meshes_.reserve(scene.meshes.size());
    for (const Mesh& mesh : scene.meshes) {
        std::vector<GpuPrimitive> primitives;
        for (const Primitive& p : mesh.primitives) primitives.push_back(upload(p));
        meshes_.push_back(std::move(primitives));
    }
}

const Material& GpuMeshes::material(int index) const {
    return index < 0 ? defaultMaterial_ : materials_.at(static_cast<std::size_t>(index));
}

}  // namespace mini
