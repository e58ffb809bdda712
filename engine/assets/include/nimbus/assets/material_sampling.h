#pragma once
// A glTF material evaluated at a surface point on the CPU: the reference renderer's shading and the
// ray caster's alpha cutouts read it, and the real-time shaders compute the same thing per fragment.
//
//   base colour = baseColorFactor × baseColorTexture × COLOR_0   (rgb and alpha alike)
//   metallic    = metallicFactor × texture.b,  roughness = roughnessFactor × texture.g
//   emissive    = emissiveFactor × emissiveTexture.rgb
//
// Textures are read at their KHR_texture_transform'ed TEXCOORD_n. Texels are sRGB-decoded first
// (base colour and emissive rgb; alpha and metallic-roughness are linear), then filtered bilinearly
// (nearest when the sampler's magFilter is NEAREST) with the sampler's wrap modes, texel centres at
// (i + 0.5)/size, no mipmaps: what the rasteriser's textures do when magnified.
//
// Does not: normal or occlusion textures (not drawn), or mipmapping.
#include <array>

#include <glm/glm.hpp>

#include "nimbus/assets/scene.h"

namespace nimbus::assets {

// What a primitive carries at the point: interpolated texture coordinates and COLOR_0.
struct SurfaceAttributes {
    glm::dvec2 uv0{0.0}, uv1{0.0};
    glm::dvec4 color{1.0};  // COLOR_0, or 1 when the primitive has none
};

struct MaterialSample {
    glm::dvec4 baseColor{1.0};  // linear rgb, alpha
    double metallic = 1.0;
    double roughness = 1.0;
    glm::dvec3 emissive{0.0};   // radiance
};

class MaterialSampler {
public:
    explicit MaterialSampler(const Scene& scene);  // the scene must outlive the sampler

    // `material` −1 is the glTF default material (white, metallic 1, roughness 1).
    MaterialSample sample(int material, const SurfaceAttributes& at) const;
    // The base colour's alpha alone (what alpha cutouts compare with alphaCutoff).
    double alpha(int material, const SurfaceAttributes& at) const;
    const Material& material(int index) const;

    // A texture at texture coordinates uv: rgb sRGB-decoded when `srgb`, alpha always linear.
    glm::dvec4 sampleTexture(int texture, const glm::dvec2& uv, bool srgb) const;

private:
    glm::dvec4 sampleRef(const TextureRef& ref, const SurfaceAttributes& at, bool srgb) const;

    const Scene& scene_;
    Material default_;
    std::array<float, 256> srgb_{};
};

}  // namespace nimbus::assets
