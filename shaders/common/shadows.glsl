// Mesh shadow maps: one layer per light view in a depth array, reversed Z (closer to the light =
// larger value), compared with GL_GEQUAL so a lookup returns the lit fraction. Needs lights.glsl
// and light_views.glsl. PCF_RADIUS, when the program defines it, fixes the kernel at compile time
// (llvmpipe then runs no loop for the fast tier's single tap); else frame.counts.w says it.
#include "common/shadow_views.glsl"
layout(binding = 1) uniform sampler2DArrayShadow shadowMap;

// Fraction of PCF taps around `clip` (the offset point's clip coordinates in view v) that see the light.
float shadowLookup(GpuLightView v, vec4 clip) {
    vec3 ndc = clip.xyz / clip.w;
    vec2 uv = ndc.xy * 0.5 + 0.5;
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0))) || clip.w <= 0.0) return 1.0;
#if defined(PCF_RADIUS) && PCF_RADIUS == 0
    return texture(shadowMap, vec4(shadowLayerUv(v, uv), v.params2.x, ndc.z));
#else
#ifdef PCF_RADIUS
    const int radius = PCF_RADIUS;
#else
    int radius = frame.counts.w;
#endif
    vec2 texelUv = vec2(1.0 / (float(frame.counts.z) * v.params.w));  // in the view's image
    float lit = 0.0;
    int y = -radius;
    do {
        int x = -radius;
        do {
            lit += texture(shadowMap, vec4(shadowLayerUv(v, uv + vec2(x, y) * texelUv), v.params2.x, ndc.z));
        } while (++x <= radius);
    } while (++y <= radius);
    float taps = float((2 * radius + 1) * (2 * radius + 1));
    return lit / taps;
#endif
}

// Fraction of PCF taps that see light `lightIndex` from p, looked up from p + offsetDir · offset.
// A cube's faces share the first's offset scale (one field of view and size); each has its own
// depth planes, which give the reversed-Z clip depth n(f − z)/(f − n) of reversedPerspective.
// `count`: the light's view count, a constant where the caller knows it (opaque.frag).
float meshVisibilityOf(int lightIndex, int count, vec3 p, vec3 offsetDir) {
    GpuLight L = lights[lightIndex];
    int first = int(L.spot.z);
    if (first < 0) return 1.0;
    int face = lightViewFace(count, L.position.xyz, p);
    GpuLightView single = shadowViews[first];
    float depth;
    lightViewPoint(single, count, face, L.position.xyz, p, depth);
    float unused;
    vec4 clip = lightViewPoint(single, count, face, L.position.xyz, p + offsetDir * shadowOffset(single, max(depth, 0.0)), unused);
    GpuLightView v = shadowViews[first + face];
    float n = v.params.y, f = v.params.z;
    if (count == 6) clip.z = n * (f - clip.w) / (f - n);
    return shadowLookup(v, clip);
}

float meshVisibility(int lightIndex, vec3 p, vec3 offsetDir) { return meshVisibilityOf(lightIndex, int(lights[lightIndex].spot.w), p, offsetDir); }

// The same for a light with at most one view, from p's clip coordinates `clip` in it and the
// normal offset's image `offsetClip` there, both from the vertex stage (opaque.vert): linear in p,
// and on a flat face so is the offset, so interpolating them is exact there.
float meshVisibilityAt(int lightIndex, vec4 clip, vec4 offsetClip) {
    int first = int(lights[lightIndex].spot.z);
    float lit = shadowLookup(shadowViews[max(first, 0)], clip + offsetClip);
    return first < 0 ? 1.0 : lit;
}
