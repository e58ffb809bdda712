// Medium optical depth towards a light, from the light's slices (DESIGN.md §3 light-slice system).
// Slice k (0-based) of a view holds the optical depth accumulated from the light up to view depth
// near + (k+1)(far − near)/K; depth `near` has zero. Between slices τ is interpolated linearly,
// so τ is exact at every slice plane. Needs lights.glsl and light_views.glsl.
layout(std140, binding = 3) uniform TransmittanceViews { GpuLightView transmittanceViews[MAX_LIGHT_VIEWS]; };
layout(binding = 2) uniform sampler2DArray transmittanceSlices;

float sliceValue(vec2 uv, float firstLayer, int k) {
    vec4 texel = texture(transmittanceSlices, vec3(uv, firstLayer + float(k / 4)));
    int c = k - 4 * (k / 4);
    return c == 0 ? texel.x : c == 1 ? texel.y : c == 2 ? texel.z : texel.w;
}

// The optical depth one light view's slices hold at p.
float viewOpticalDepth(GpuLightView v, vec3 p) {
    vec2 uv;
    if (!lightViewUv(v, p, uv)) return 0.0;  // slices cover the medium: outside them there is none
    float depth = -(v.view * vec4(p, 1.0)).z;
    int K = int(v.params.w);
    float s = (depth - v.params.y) / (v.params.z - v.params.y) * float(K);
    if (s <= 0.0) return 0.0;
    // Two fetches whatever s is (llvmpipe runs every branch): the enclosing slices, or the last one
    // past the medium.
    int k = min(int(floor(s)), K - 1);
    float lo = k == 0 ? 0.0 : sliceValue(uv, v.params2.x, max(k - 1, 0));
    float hi = sliceValue(uv, v.params2.x, k);
    return s >= float(K) ? hi : mix(lo, hi, s - float(k));
}

float mediumOpticalDepth(int lightIndex, vec3 p) {
    if (frame.counts.y == 0) return 0.0;
    GpuLight L = lights[lightIndex];
    int first = int(L.media.x);
    if (first < 0) return 0.0;
    return viewOpticalDepth(transmittanceViews[lightViewIndex(first, int(L.media.y), L.position.xyz, p)], p);
}
