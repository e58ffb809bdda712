#pragma once
// How a glTF material reaches the opaque and shadow shaders (shaders/common/material.glsl): the
// features that pick a program variant, and the uniforms and textures of one draw.
#include <string>
#include <vector>

#include "nimbus/render/gpu_scene.h"

namespace nimbus::render {

// Bits of a material (and primitive) that change the shader; each is one define.
enum MaterialFeature : unsigned {
    kBaseColorTexture = 1u,
    kMetallicRoughnessTexture = 2u,
    kEmissiveTexture = 4u,
    kAlphaMask = 8u,
    kVertexColor = 16u,
};

inline constexpr GLuint kBaseColorUnit = 0;
inline constexpr GLuint kMetallicRoughnessUnit = 4;
inline constexpr GLuint kEmissiveUnit = 5;

unsigned materialFeatures(const GpuMaterial& material, const GpuPrimitive& primitive);

// What the shadow pass needs of them: nothing for an opaque material; a cutout's alpha otherwise.
unsigned shadowFeatures(unsigned features);

std::vector<std::string> featureDefines(unsigned features);

// Sets the uniforms `features` make active and binds the textures. `shading`: the opaque pass
// (all terms); otherwise the shadow pass (the cutout only).
void bindMaterial(GLuint program, const GpuScene& scene, const GpuMaterial& material, unsigned features, bool shading);

}  // namespace nimbus::render
