// A glTF material's uniforms (render/src/material_binding.cpp sets them), shared by the opaque and
// shadow passes. Program variants are compiled per material: BASE_COLOR_TEXTURE,
// METALLIC_ROUGHNESS_TEXTURE, EMISSIVE_TEXTURE, ALPHA_MASK and VERTEX_COLOR say what a draw reads,
// so a fragment does no work for what its material lacks.
layout(location = 2) uniform vec4 uBaseColorFactor;  // linear rgb, alpha
layout(location = 3) uniform vec4 uMaterial;         // metallic, roughness, alpha cutoff, unused
#ifdef BASE_COLOR_TEXTURE
layout(location = 5) uniform vec3 uBaseColorUv[2];   // KHR_texture_transform rows (assets::TextureRef)
layout(location = 11) uniform int uBaseColorTexCoord;
layout(binding = 0) uniform sampler2D uBaseColor;    // sRGB
#endif
#ifdef METALLIC_ROUGHNESS_TEXTURE
layout(location = 7) uniform vec3 uMetallicRoughnessUv[2];
layout(location = 12) uniform int uMetallicRoughnessTexCoord;
layout(binding = 4) uniform sampler2D uMetallicRoughness;  // linear: g roughness, b metalness
#endif
#ifdef EMISSIVE_TEXTURE
layout(location = 9) uniform vec3 uEmissiveUv[2];
layout(location = 13) uniform int uEmissiveTexCoord;
layout(binding = 5) uniform sampler2D uEmissive;     // sRGB
#endif

// A texture's coordinates: its TEXCOORD set, then its transform (per vertex: affine maps interpolate).
vec2 materialUv(vec3 rows[2], int texCoord, vec2 uv0, vec2 uv1) {
    vec3 uv = vec3(texCoord == 1 ? uv1 : uv0, 1.0);
    return vec2(dot(rows[0], uv), dot(rows[1], uv));
}
