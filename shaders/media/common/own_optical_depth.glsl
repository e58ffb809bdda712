// A particle's own share of the light slices (media/host/light_transmittance.glsl). The slices hold every
// particle's optical depth at slice planes and texel centres, read linearly between them, so a
// particle thinner than the slice spacing or a texel shades itself with its own optical depth
// spread over the slice interval and the texels around it, and its lit skin goes dark. Where the
// slices do not resolve a particle, what they hold of it at p is recomputed as light_slices.frag
// wrote it, taken out, and its exact optical depth from the light to p put in. Other particles'
// spread stays: a slice map cannot tell them apart. Blocks do the same with a block's particles
// (block_own_optical_depth.glsl). Needs media/host/light_transmittance.glsl and media/common/optics.glsl.

// The particle's optical depth along a light-view ray from where the ray starts (the light, for a
// perspective view) up to ray parameter t, integrated as light_slices.frag does.
float ownDepthUpTo(Chord c, float radius, float sigma, bool fromLight, float t) {
    if (c.halfChord <= 0.0) return 0.0;
    float start = fromLight ? max(-c.halfChord, -c.tClosest) : -c.halfChord;
    return sigma * chordIntegral(c, radius, start, t - c.tClosest);
}

// The light-view ray through a point `onPlane` of the plane at view depth 1 (perspective: from the
// light; orthographic: from the view's z = 0 plane, along −z). `stretch`: ray parameter per unit depth.
Chord lightViewChord(bool perspective, vec2 onPlane, vec3 centre, float radius, out float stretch) {
    if (perspective) {
        vec3 d = vec3(onPlane, -1.0);
        stretch = length(d);
        return chordOf(vec3(0.0), d / stretch, centre, radius);
    }
    stretch = 1.0;
    return chordOf(vec3(onPlane, 0.0), vec3(0.0, 0.0, -1.0), centre, radius);
}

// What mediaViewOpticalDepth(v, p) reads: the slice interval around p's depth and the four texels of
// its bilinear filter, each with its weight and its ray (a point of the plane at depth 1).
struct SliceRead {
    bool inView;       // false: p lies outside the view, where the slices hold nothing of any particle
    bool holds;        // false: outside the view or before the first plane, where the slices hold zero
    bool perspective;
    vec3 pView;        // p in light view space
    float depth;       // p's view depth
    bool firstSlice;   // the interval starts at the first plane, which holds zero
    float f;           // where p lies in the interval
    float nearPlane;   // the interval's planes (view depth)
    float farPlane;
    vec2 onPlane[4];
    float weight[4];
};

SliceRead sliceRead(GpuLightView v, vec3 p) {
    SliceRead r;
    r.perspective = v.params.x > 0.5;
    r.pView = (v.view * vec4(p, 1.0)).xyz;
    r.depth = -r.pView.z;
    vec2 uv;
    int K = int(v.params.w);
    float spacing = (v.params.z - v.params.y) / float(K);
    float s = (r.depth - v.params.y) / spacing;
    r.inView = lightViewUv(v, p, uv);
    r.holds = r.inView && s > 0.0;
    int k = min(int(floor(max(s, 0.0))), K - 1);
    r.firstSlice = k == 0;
    r.f = s >= float(K) ? 1.0 : s - float(k);
    r.nearPlane = v.params.y + float(k) * spacing;
    r.farPlane = r.nearPlane + spacing;
    // The view's own texels: a lamp's may be fewer than the array's (light_transmittance.glsl mediaSliceCount).
    vec2 size = vec2(r.perspective && mediaSliceCount.z > 0 ? ivec2(mediaSliceCount.z) : textureSize(mediaSlices, 0).xy);
    vec2 texel = uv * size - 0.5;
    vec2 base = floor(texel), w = texel - base;
    for (int j = 0; j < 4; ++j) {
        vec2 corner = vec2(float(j & 1), float(j >> 1));
        r.weight[j] = mix(1.0 - w.x, w.x, corner.x) * mix(1.0 - w.y, w.y, corner.y);
        vec2 ndc = (clamp(base + corner, vec2(0.0), size - 1.0) + 0.5) / size * 2.0 - 1.0;  // clamp to edge
        r.onPlane[j] = ndc * v.params2.zw;
    }
    return r;
}

// The light-view ray through p, as a point of the plane at depth 1 (lightViewChord).
vec2 sliceReadOwnRay(SliceRead r) { return r.perspective ? r.pView.xy / max(r.depth, 1e-30) : r.pView.xy; }

// x: what mediaViewOpticalDepth(v, p) holds of the particle (slice planes interpolated, four texels
// filtered); y: its exact optical depth from the light to p.
vec2 ownOpticalDepth(GpuLightView v, vec3 p, vec4 positionRadius, float sigma) {
    SliceRead r = sliceRead(v, p);
    if (!r.inView) return vec2(0.0);
    vec3 centre = (v.view * vec4(positionRadius.xyz, 1.0)).xyz;
    float radius = positionRadius.w, stretch;
    Chord toP = lightViewChord(r.perspective, sliceReadOwnRay(r), centre, radius, stretch);
    float exact = ownDepthUpTo(toP, radius, sigma, r.perspective, r.depth * stretch);
    if (!r.holds) return vec2(0.0, exact);
    float smeared = 0.0;
    for (int j = 0; j < 4; ++j) {
        if (!(r.weight[j] > 0.0)) continue;
        Chord c = lightViewChord(r.perspective, r.onPlane[j], centre, radius, stretch);
        if (c.halfChord <= 0.0) continue;
        float lo = r.firstSlice ? 0.0 : ownDepthUpTo(c, radius, sigma, r.perspective, r.nearPlane * stretch);
        float hi = ownDepthUpTo(c, radius, sigma, r.perspective, r.farPlane * stretch);
        smeared += r.weight[j] * mix(lo, hi, r.f);
    }
    return vec2(smeared, exact);
}

// Whether view v's slices resolve a particle of this radius and peak extinction at p: slice planes
// and texels no farther apart than it is wide, and neither holding more than an optical depth of 2
// of it. Read linearly between planes, a dense particle's own τ rises across its lit skin as a
// chord over a cliff, and the light its skin scatters comes out far too dark.
// block_composite_pass.cpp blocksOfUnresolvedParticles decides the same for blocks.
bool slicesResolve(GpuLightView v, vec3 p, float radius, float sigma) {
    float spacing = (v.params.z - v.params.y) / max(v.params.w, 1.0);
    float texel = v.params2.y * (v.params.x > 0.5 ? max(-(v.view * vec4(p, 1.0)).z, 0.0) : 1.0);
    return spacing <= 2.0 * radius && texel <= radius && sigma * max(spacing, texel) <= 2.0;
}

// The light view of light i whose slices hold p, or −1 where the light has none.
int lightSliceView(int i, vec3 p) { return mediaLightSliceView(i, lights[i].position.xyz, p); }

// The medium's optical depth towards light i that a point p of `particle` receives: the slices',
// with the particle's own share made exact where they do not resolve it.
float particleLightDepth(int i, vec3 p, GpuParticle particle) {
    int view = lightSliceView(i, p);
    if (view < 0) return 0.0;
    GpuLightView v = mediaSliceViews[view];
    float slices = mediaViewOpticalDepth(v, p);
    if (slicesResolve(v, p, particle.positionRadius.w, particle.albedoSigma.w)) return slices;
    vec2 own = ownOpticalDepth(v, p, particle.positionRadius, particle.albedoSigma.w);
    return max(slices - own.x, 0.0) + own.y;
}
