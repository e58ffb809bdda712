// Mesh shadows: PCF over the shadow-map array with a compare sampler (GL_GEQUAL on reversed Z, so
// a tap returns 1 where p is at least as near the light as the stored surface). The lookup point is
// pushed 1.5 texels along the normal against acne. Needs mini_frame.glsl.
layout(binding = 1) uniform sampler2DArrayShadow miniShadowMap;

// The cube face of a direction, 0..5 = +X −X +Y −Y +Z −Z (gpu::makeLightViews' point-light order).
int miniCubeFace(vec3 d) {
    vec3 a = abs(d);
    if (a.x >= a.y && a.x >= a.z) return d.x >= 0.0 ? 0 : 1;
    if (a.y >= a.z) return d.y >= 0.0 ? 2 : 3;
    return d.z >= 0.0 ? 4 : 5;
}

// Fraction of the (2r+1)² taps that see light i from p; 1 outside the light's views.
float miniShadowVisibility(int i, vec3 p, vec3 n) {
    MiniLight L = miniLights[i];
    int first = int(L.spot.z);
    if (first < 0) return 1.0;
    int index = int(L.spot.w) == 6 ? first + miniCubeFace(p - L.position.xyz) : first;
    MiniShadowView v = miniShadowViews[index];
    float depth = max(-(v.view * vec4(p, 1.0)).z, 0.0);
    float texel = v.params.y * (v.params.x > 0.5 ? depth : 1.0);
    vec4 clip = v.viewProjection * vec4(p + n * (1.5 * texel), 1.0);
    vec3 ndc = clip.xyz / clip.w;
    vec2 uv = ndc.xy * 0.5 + 0.5;
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0))) || clip.w <= 0.0) return 1.0;
    int radius = miniFrame.counts.z;
    vec2 texelUv = vec2(1.0 / float(miniFrame.counts.y));
    float lit = 0.0;
    // do-while, not for: llvmpipe runs a for body once more under an empty mask.
    int y = -radius;
    do {
        int x = -radius;
        do {
            lit += texture(miniShadowMap, vec4(uv + vec2(x, y) * texelUv, v.params.z, ndc.z));
        } while (++x <= radius);
    } while (++y <= radius);
    return lit / float((2 * radius + 1) * (2 * radius + 1));
}
