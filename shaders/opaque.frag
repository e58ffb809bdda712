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
// MEDIA_LIGHT_TRANSMITTANCE: the media plugin's light slices (render::MeshShadingInput); MEDIA_SLICE_CROPS with it:
// some light's slices come with a crop (media_render_extension.cpp).
#ifdef MEDIA_LIGHT_TRANSMITTANCE
#include "media/host/light_transmittance.glsl"
#endif

in vec3 vPosition;
in vec3 vNormal;
// VERTEX_LIGHTS: how many of the first lights come with light-view coordinates from opaque.vert
// (VERTEX_DIRECTIONAL_LIGHTS: bit i set when light i of them is directional);
// FRAGMENT_LIGHTS: whether any light follows them. Both are compile-time (render/opaque_pass.cpp)
// because llvmpipe runs a branch or a loop body under a mask even when no lane takes it.
#if VERTEX_LIGHTS > 0
in vec4 vShadowClip[VERTEX_LIGHTS];
in vec4 vShadowOffset[VERTEX_LIGHTS];
#ifdef MEDIA_LIGHT_TRANSMITTANCE
in vec4 vSliceClip[VERTEX_LIGHTS];
#ifdef MEDIA_SLICE_CROPS
in vec4 vCropClip[VERTEX_LIGHTS];
#endif
in float vSliceDepth[VERTEX_LIGHTS];
#endif
#endif
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

// One light's term. Back-facing and shadowed points add an exact zero instead of skipping the light:
// a `continue` cost llvmpipe more than the arithmetic it skips. max() keeps the BRDF finite on a
// back face (its formula assumes n·l ≥ 0); the select makes the term zero there whatever the
// shadow and slice lookups return.
vec3 lightTerm(SurfaceBrdf brdf, vec3 n, vec3 v, LightSample s, float visibility, float transmittance) {
    float cosine = dot(n, s.toLight);
    vec3 term = brdfTimesCosine(brdf, n, v, s.toLight, max(cosine, 0.0)) * s.irradiance * (visibility * transmittance);
    return cosine > 0.0 ? term : vec3(0.0);
}

#if VERTEX_LIGHTS > 0
// Light i (< VERTEX_LIGHTS, a compile-time constant once inlined) from its interpolated view coordinates.
vec3 vertexLight(int i, SurfaceBrdf brdf, vec3 n, vec3 v) {
    float visibility = meshVisibilityAt(i, vShadowClip[i], gl_FrontFacing ? vShadowOffset[i] : -vShadowOffset[i]);
    float transmittance = 1.0;
#ifdef MEDIA_LIGHT_TRANSMITTANCE
    int view = mediaLightSlices[i].x;
#ifdef MEDIA_SLICE_CROPS
    // A crop's view follows its whole one; vCropClip lies outside every crop where there is none.
    float depth = mediaCroppedOpticalDepthAt(mediaSliceViews[max(view, 0)], mediaSliceViews[max(view, 0) + 1], vSliceClip[i], vCropClip[i], vSliceDepth[i]);
#else
    // A vertex light is a sun or a spot (one view): which, known here, spares the lookup the test.
    int kind = (VERTEX_DIRECTIONAL_LIGHTS & (1u << i)) != 0u ? MEDIA_VIEW_ORTHOGRAPHIC : MEDIA_VIEW_PERSPECTIVE;
    float depth = mediaViewOpticalDepthAt(mediaSliceViews[max(view, 0)], kind, vSliceClip[i], vSliceDepth[i]);
#endif
    if (mediaSliceCount.x != 0 && view >= 0) transmittance = exp(-depth);
#endif
    // Which kind the light is is known here (VERTEX_DIRECTIONAL_LIGHTS): a sun's fragments skip the
    // point and spot falloff that sampleLight would compute under a mask.
    LightSample s = (VERTEX_DIRECTIONAL_LIGHTS & (1u << i)) != 0u ? LightSample(-lights[i].direction.xyz, 1e30, lights[i].radiance.rgb)
                                                                 : sampleLight(i, vPosition);
    return lightTerm(brdf, n, v, s, visibility, transmittance);
}
#endif

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
#if VERTEX_LIGHTS > 0
    radiance += vertexLight(0, brdf, n, v);
#endif
#if VERTEX_LIGHTS > 1
    radiance += vertexLight(1, brdf, n, v);
#endif
#if VERTEX_LIGHTS > 2
    radiance += vertexLight(2, brdf, n, v);
#endif
#if VERTEX_LIGHTS > 3
    radiance += vertexLight(3, brdf, n, v);
#endif
#ifdef FRAGMENT_LIGHTS
    // do-while, not for (here and in the shaders it includes): llvmpipe runs a for loop's body once
    // more under an empty mask, which doubled the cost of a one-light frame.
    int i = VERTEX_LIGHTS;
    do {
#ifdef POINT_FRAGMENT_LIGHTS
        const int views = 6;  // or none: the lookups then return before reading any
#else
        int views = int(lights[i].spot.w);
#endif
        LightSample s = sampleLight(i, vPosition);
        float visibility = meshVisibilityOf(i, views, vPosition, n);
        float transmittance = 1.0;
#ifdef MEDIA_LIGHT_TRANSMITTANCE
        transmittance = exp(-mediaOpticalDepthOf(i, views, lights[i].position.xyz, vPosition));
#endif
        radiance += lightTerm(brdf, n, v, s, visibility, transmittance);
    } while (++i < frame.counts.x);
#endif
    outRadiance = vec4(radiance, 1.0);
}
