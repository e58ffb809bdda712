#pragma once
// The scene's meshes, materials and textures uploaded once to the GPU. Per frame the renderer
// draws instances of these primitives with origin-relative model matrices.
//
// Does not: stream, compress or re-upload on change (the editor rebuilds what it edits).
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "nimbus/assets/scene.h"
#include "nimbus/gpu/gl_objects.h"

namespace nimbus::render {

struct GpuPrimitive {
    gpu::VertexArray vertexArray;
    gpu::Buffer vertices;  // interleaved: position, normal, uv0, uv1, COLOR_0 (14 floats)
    gpu::Buffer indices;
    GLsizei indexCount = 0;
    int material = -1;
    bool vertexColors = false;  // the primitive has COLOR_0 (otherwise its colour is 1)
};

// A material as the opaque and shadow passes draw it (assets::Material with GPU texture indices).
struct GpuMaterial {
    assets::Material params;
    bool doubleSided() const { return params.doubleSided; }
    bool masked() const { return params.alphaMode == assets::AlphaMode::Mask; }
};

// One glTF texture, uploaded once per way it is read: sRGB-encoded (base colour, emissive) and/or
// linear (metallic-roughness). A texture never read one way has no GL texture for it.
struct GpuTexture {
    gpu::Texture srgb;
    gpu::Texture linear;
    gpu::Sampler sampler;
};

class GpuScene {
public:
    explicit GpuScene(const assets::Scene& scene);

    const std::vector<GpuPrimitive>& primitives(int mesh) const { return meshes_.at(static_cast<std::size_t>(mesh)); }
    const GpuMaterial& material(int index) const;  // -1 gives the glTF default material
    const GpuTexture& texture(int index) const { return textures_.at(static_cast<std::size_t>(index)); }
    std::size_t meshCount() const { return meshes_.size(); }
    // Object-space bounds of a mesh (all its primitives).
    const std::pair<glm::vec3, glm::vec3>& localBounds(int mesh) const { return bounds_.at(static_cast<std::size_t>(mesh)); }

private:
    std::vector<std::vector<GpuPrimitive>> meshes_;
    std::vector<std::pair<glm::vec3, glm::vec3>> bounds_;
    std::vector<GpuMaterial> materials_;
    std::vector<GpuTexture> textures_;
    GpuMaterial defaultMaterial_;
};

// One mesh to draw this frame.
struct MeshInstance {
    int mesh = -1;
    glm::dmat4 world{1.0};
};

}  // namespace nimbus::render
