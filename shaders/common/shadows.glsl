// Mesh shadow maps: one layer per light view in a depth array, reversed Z (closer to the light =
// larger value), compared with GL_GEQUAL so a lookup returns the lit fraction. Needs lights.glsl
// and light_views.glsl.
#include "common/shadow_views.glsl"
layout(binding = 1) uniform sampler2DArrayShadow shadowMap;

// Fraction of PCF taps that see the light from p. `offsetDir` pushes the lookup off the surface
// (the normal for meshes, the light direction for media) by a texel-sized amount to avoid acne.
float meshVisibility(int lightIndex, vec3 p, vec3 offsetDir) {
    GpuLight L = lights[lightIndex];
    int first = int(L.spot.z);
    if (first < 0) return 1.0;
    GpuLightView v = shadowViews[lightViewIndex(first, int(L.spot.w), L.position.xyz, p)];
    float depth = max(-(v.view * vec4(p, 1.0)).z, 0.0);
    float texel = v.params2.y * (v.params.x > 0.5 ? depth : 1.0);
    vec4 clip = v.viewProjection * vec4(p + offsetDir * (1.5 * texel), 1.0);
    vec3 ndc = clip.xyz / clip.w;
    vec2 uv = ndc.xy * 0.5 + 0.5;
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0))) || clip.w <= 0.0) return 1.0;
    int radius = frame.counts.w;
    vec2 texelUv = vec2(1.0 / float(frame.counts.z));
    float lit = 0.0;
    int y = -radius;
    do {
        int x = -radius;
        do {
            lit += texture(shadowMap, vec4(uv + vec2(x, y) * texelUv, v.params2.x, ndc.z));
        } while (++x <= radius);
    } while (++y <= radius);
    float taps = float((2 * radius + 1) * (2 * radius + 1));
    return lit / taps;
}
