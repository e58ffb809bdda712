#pragma once
// The scene's meshes on the GPU: one vertex array per primitive (positions and normals in two
// buffers, 32-bit indices), plus the materials.
#include <vector>

#include "gltf_scene.h"
#include "nimbus/gpu/gl_objects.h"

namespace mini {

struct GpuPrimitive {
    nimbus::gpu::Buffer positions, normals, indices;
    nimbus::gpu::VertexArray vertexArray;  // attribute 0: position, 1: normal
    GLsizei indexCount = 0;
    int material = -1;
};

class GpuMeshes {
public:
    explicit GpuMeshes(const Scene& scene);

    const std::vector<GpuPrimitive>& primitives(int mesh) const { return meshes_.at(static_cast<std::size_t>(mesh)); }
    const Material& material(int index) const;  // −1: the glTF default material

private:
    std::vector<std::vector<GpuPrimitive>> meshes_;
    std::vector<Material> materials_;
    Material defaultMaterial_;
};

}  // namespace mini
