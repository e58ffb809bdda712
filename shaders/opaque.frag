#version 450 core
// glTF metallic-roughness meshes (docs/scene-format.md §4.1):
//   L_s = Σ_l f(l, v) E_l max(0, n·l) V_mesh T_l + baseColor · L_amb + emissive
// f: common/surface_brdf.glsl. V_mesh from the mesh shadow maps (PCF), T_l = exp(−τ) from the
// medium's light slices when an extension provides them (1 otherwise). ALPHA_MASK cuts the
// surface where the base colour's alpha is below the cutoff.
#include "common/math.glsl"
#include "common/frame.glsl"
#include "common/lights.glsl"
#include "common/light_views.glsl"
#include "common/shadows.glsl"
#include "common/material.glsl"
#include "common/surface_brdf.glsl"
// MEDIA_LIGHT_TRANSMITTANCE: the media plugin's light slices (render::MeshShadingInput).
#ifdef MEDIA_LIGHT_TRANSMITTANCE
#include "media/host/light_transmittance.glsl"
#endif

in vec3 vPosition;
in vec3 vNormal;
#ifdef VERTEX_COLOR
in vec4 vColor;
#endif
#ifdef BASE_COLOR_TEXTURE
in vec2 vBaseColorUv;
#endif
#ifdef METALLIC_ROUGHNESS_TEXTURE
in vec2 vMetallicRoughnessUv;
#endif
#ifdef EMISSIVE_TEXTURE
in vec2 vEmissiveUv;
#endif

layout(location = 4) uniform vec3 uEmissiveFactor;

layout(location = 0) out vec4 outRadiance;

void main() {
    vec4 base = uBaseColorFactor;
#ifdef VERTEX_COLOR
    base *= vColor;
#endif
#ifdef BASE_COLOR_TEXTURE
    base *= texture(uBaseColor, vBaseColorUv);
#endif
#ifdef ALPHA_MASK
    if (base.a < uMaterial.z) discard;
#endif
    vec2 metallicRoughness = uMaterial.xy;
#ifdef METALLIC_ROUGHNESS_TEXTURE
    metallicRoughness *= texture(uMetallicRoughness, vMetallicRoughnessUv).bg;
#endif
    vec3 emissive = uEmissiveFactor;
#ifdef EMISSIVE_TEXTURE
    emissive *= texture(uEmissive, vEmissiveUv).rgb;
#endif
    vec3 n = normalize(vNormal);
    if (!gl_FrontFacing) n = -n;  // only double-sided materials reach here from behind
    vec3 v = frameOrthographic() ? -frame.cameraForward.xyz : -normalize(vPosition);  // towards the eye
    SurfaceBrdf brdf = surfaceBrdf(base.rgb, metallicRoughness.x, metallicRoughness.y);

    vec3 radiance = base.rgb * frame.ambient.rgb + emissive;
    int i = 0;
    // do-while, not for (here and in the shaders it includes): llvmpipe runs a for loop's body once
    // more under an empty mask, which doubled the cost of a one-light frame.
    if (frame.counts.x > 0) do {
        LightSample s = sampleLight(i, vPosition);
        float cosine = dot(n, s.toLight);
        if (cosine <= 0.0) continue;
        float visibility = meshVisibility(i, vPosition, n);
        if (visibility <= 0.0) continue;
        float transmittance = 1.0;
#ifdef MEDIA_LIGHT_TRANSMITTANCE
        transmittance = mediaTransmittance(i, lights[i].position.xyz, vPosition);
#endif
        radiance += brdfTimesCosine(brdf, n, v, s.toLight, cosine) * s.irradiance * (visibility * transmittance);
    } while (++i < frame.counts.x);
    outRadiance = vec4(radiance, 1.0);
}
