// The mesh shadow map read as raw depth, for the medium (lighting.glsl, particle_splats.frag): a
// comparison with the receiver's depth along the light, softened over a depth, never a hard cut.
// Needs common/lights.glsl and common/light_views.glsl.
#include "media/bindings.glsl"
#include "common/shadow_views.glsl"
layout(binding = MEDIA_SHADOW_DEPTH_UNIT) uniform sampler2DArray uShadowDepth;  // the mesh shadow map, read as raw depth

// Light-view depth stored in a shadow map texel (reversed Z), back to metres along the light axis.
float shadowTexelDepth(GpuLightView v, float stored) {
    float n = v.params.y, f = v.params.z;
    if (v.params.x < 0.5) return n + (1.0 - stored) * (f - n);
    float a = n / (f - n), b = n * f / (f - n);
    return stored + a > 0.0 ? b / (stored + a) : 1e30;
}

// How far p lies in front of the shadow map's occluder along the light (metres; > 0 lit), at one
// tap without filtering. Very large where nothing casts a shadow there.
// `count`: the light's view count, a constant where the caller knows it (splat_source.glsl).
float meshShadowMarginOf(int lightIndex, int count, vec3 p) {
    GpuLight L = lights[lightIndex];
    int first = int(L.spot.z);
    if (first < 0) return 1e30;
    int face = lightViewFace(count, L.position.xyz, p);
    float receiver;
    vec4 clip = lightViewPoint(shadowViews[first], count, face, L.position.xyz, p, receiver);
    GpuLightView v = shadowViews[first + face];
    vec2 uv;
    if (!lightViewClipUv(clip, uv)) return 1e30;
    return shadowTexelDepth(v, texture(uShadowDepth, vec3(shadowLayerUv(v, uv), v.params2.x)).r) - receiver;
}

float meshShadowMargin(int lightIndex, vec3 p) { return meshShadowMarginOf(lightIndex, int(lights[lightIndex].spot.w), p); }

// The same comparison at one shadow-map tap, without the lateral filter: 1 lit, 0 shadowed, soft
// only over the particle's depth extent.
float meshVisibilityTapOf(int lightIndex, int count, vec3 p, float softness) {
    return 0.5 * (1.0 + erfApprox(meshShadowMarginOf(lightIndex, count, p) / (max(softness, 1e-4) * 1.41421356)));
}

float meshVisibilityTap(int lightIndex, vec3 p, float softness) { return meshVisibilityTapOf(lightIndex, int(lights[lightIndex].spot.w), p, softness); }
