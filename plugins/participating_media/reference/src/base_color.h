#pragma once
// glTF baseColor at a mesh hit: material factor × texture. Texels are sRGB-decoded first, then
// filtered bilinearly (nearest when the sampler's magFilter is NEAREST) with the sampler's wrap modes,
// texel centres at (i + 0.5)/size, no mipmaps: what the rasteriser's SRGB8 textures do when magnified.
//
// Does not: use alpha (meshes are opaque), vertex colours, or any PBR term but baseColor.
#include <vector>

#include <glm/glm.hpp>

#include "nimbus/assets/scene.h"
#include "nimbus/raycast/mesh_raycaster.h"

namespace nimbus::media::reference {

class BaseColorSampler {
public:
    explicit BaseColorSampler(const assets::Scene& scene);

    glm::dvec3 at(const raycast::MeshHit& hit) const;

    // The texture alone at texture coordinates uv (linear RGB).
    glm::dvec3 sampleTexture(int texture, glm::dvec2 uv) const;

private:
    struct LinearImage {
        int width = 0, height = 0;
        std::vector<glm::vec3> texels;  // linear RGB, row 0 = top (v = 0)
    };
    const assets::Scene& scene_;
    std::vector<LinearImage> images_;  // per scene image, decoded once
};

}  // namespace nimbus::media::reference
