// Light arriving at a point inside the medium and scattered towards the camera (DESIGN.md §2):
//   J = albedo · (Σ_l p(θ) E_l V_mesh T_l + L_amb) + emission      (per unit optical depth)
// T_l = exp(−τ) from the light slices; V_mesh from the mesh shadow map with the smooth weighting of
// seed 001 §III (never a hard cut through a billboard). Needs common/frame, lights, light_views,
// transmittance, media/optics.
#include "common/shadow_views.glsl"
layout(binding = 4) uniform sampler2DArray uShadowDepth;  // the mesh shadow map, read as raw depth

// Light-view depth stored in a shadow map texel (reversed Z), back to metres along the light axis.
float shadowTexelDepth(GpuLightView v, float stored) {
    float n = v.params.y, f = v.params.z;
    if (v.params.x < 0.5) return n + (1.0 - stored) * (f - n);
    float a = n / (f - n), b = n * f / (f - n);
    return stored + a > 0.0 ? b / (stored + a) : 1e30;
}

// Seed 001 §III: instead of a lit/unlit test per pixel, compare the occluder depth the shadow map
// stores with the receiver's depth and weight smoothly over the particle's own depth extent: the
// fraction of a Gaussian of standard deviation `softness` (R/3) that lies in front of the occluder.
// The 3×3 taps are spread over ±softness across the light's view, not over shadow-map texels: a
// particle is lit over the whole extent of its kernel, so a shadow boundary crossing it should fade
// over that width (the reference integrates visibility along each ray through the kernel), not cut
// at one texel. 1 = fully lit.
float mediumMeshVisibility(int lightIndex, vec3 p, float softness) {
    GpuLight L = lights[lightIndex];
    int first = int(L.spot.z);
    if (first < 0) return 1.0;
    GpuLightView v = shadowViews[lightViewIndex(first, int(L.spot.w), L.position.xyz, p)];
    vec2 uv;
    if (!lightViewUv(v, p, uv)) return 1.0;  // outside the shadow map: nothing casts there
    float receiver = -(v.view * vec4(p, 1.0)).z;
    float width = max(softness, 1e-4) * 1.41421356;
    // The light view's right and up axes in world space (rows of its rotation).
    vec3 right = vec3(v.view[0][0], v.view[1][0], v.view[2][0]);
    vec3 up = vec3(v.view[0][1], v.view[1][1], v.view[2][1]);
    float lit = 0.0;
    for (int y = -1; y <= 1; ++y) {
        for (int x = -1; x <= 1; ++x) {
            vec2 tapUv;
            if (!lightViewUv(v, p + (right * float(x) + up * float(y)) * softness, tapUv)) {
                lit += 1.0;
                continue;
            }
            float occluder = shadowTexelDepth(v, texture(uShadowDepth, vec3(tapUv, v.params2.x)).r);
            lit += 0.5 * (1.0 + erfApprox((occluder - receiver) / width));
        }
    }
    return lit / 9.0;
}

// The same comparison at one shadow-map tap, without the lateral filter: 1 lit, 0 shadowed, soft
// only over the particle's depth extent.
float meshVisibilityTap(int lightIndex, vec3 p, float softness) {
    GpuLight L = lights[lightIndex];
    int first = int(L.spot.z);
    if (first < 0) return 1.0;
    GpuLightView v = shadowViews[lightViewIndex(first, int(L.spot.w), L.position.xyz, p)];
    vec2 uv;
    if (!lightViewUv(v, p, uv)) return 1.0;
    float receiver = -(v.view * vec4(p, 1.0)).z;
    float occluder = shadowTexelDepth(v, texture(uShadowDepth, vec3(uv, v.params2.x)).r);
    return 0.5 * (1.0 + erfApprox((occluder - receiver) / (max(softness, 1e-4) * 1.41421356)));
}

// Light i scattered towards the camera at p, per unit optical depth and albedo: p(θ) E V T.
// `attenuation` ≥ 0 replaces the point/spot light's falloff (shape / d²) at p with a value averaged
// over the particle (see kernelMeanAttenuation); < 0 keeps sampleLight's. Likewise `visibility` ≥ 0
// replaces the mesh visibility at p (see segmentVisibility).
vec3 scatteredLight(int i, vec3 p, vec3 viewDir, GpuParticle particle, float attenuation, float visibility) {
    LightSample s = sampleLight(i, p);
    vec3 irradiance = attenuation >= 0.0 ? lights[i].radiance.rgb * attenuation : s.irradiance;
    if (all(lessThanEqual(irradiance, vec3(0.0)))) return vec3(0.0);
    // θ between the light's travel direction (−toLight) and the direction to the camera (−viewDir).
    float phase = phaseValue(particle.extra.x, particle.emissionG.w, s.toLight, viewDir);
    if (visibility < 0.0) visibility = mediumMeshVisibility(i, p, particle.positionRadius.w / 3.0);
    if (visibility <= 0.0) return vec3(0.0);
    return phase * irradiance * (visibility * exp(-mediumOpticalDepth(i, p)));
}

// Source radiance per unit optical depth at p for a particle seen along `viewDir`:
// albedo · (Σ p E V T + L_amb) + emission.
vec3 mediumSource(vec3 p, vec3 viewDir, GpuParticle particle) {
    vec3 scattered = frame.ambient.rgb;
    for (int i = 0; i < frame.counts.x; ++i) scattered += scatteredLight(i, p, viewDir, particle, -1.0, -1.0);
    return particle.albedoSigma.rgb * scattered + particle.emissionG.rgb;
}

// The kernel-weighted mean, over the segment [lo, hi] (u from the chord's closest point), of a
// point/spot light's falloff shape(x)/d², and the u where that falloff is centred. Near the light
// 1/d² peaks far more sharply than the kernel varies, so one sample is badly wrong; with
// u = u_l + b·tan φ the integral ∫ρ·shape/d² du becomes (1/b)∫ρ·shape dφ, smooth in φ (the spot
// cone and range window included, per node), which six Gauss–Legendre points integrate well.
vec2 kernelMeanAttenuation(vec3 origin, vec3 dir, Chord c, float radius, float lo, float hi, int light) {
    vec3 toLight = lights[light].position.xyz - origin;
    float tLight = dot(toLight, dir);
    float b = max(length(toLight - tLight * dir), 1e-4 * radius);
    float uLight = tLight - c.tClosest;
    float phi0 = atan((lo - uLight) / b), phi1 = atan((hi - uLight) / b);
    float k = KERNEL_FALLOFF / (radius * radius);
    const float nodes[3] = float[](0.2386191861, 0.6612093865, 0.9324695142);
    const float weights[3] = float[](0.4679139346, 0.3607615730, 0.1713244924);
    float mid = 0.5 * (phi0 + phi1), half_ = 0.5 * (phi1 - phi0), sum = 0.0, weightedU = 0.0;
    for (int j = 0; j < 3; ++j) {
        for (int sgn = -1; sgn <= 1; sgn += 2) {
            float u = uLight + b * tan(mid + float(sgn) * half_ * nodes[j]);
            float w = weights[j] * exp(-k * u * u) * lightShape(light, origin + dir * (c.tClosest + u));
            sum += w;
            weightedU += w * u;
        }
    }
    float mass = gaussianSegment(sqrt(k), lo, hi);
    float mean = mass > 0.0 ? half_ * sum / (b * mass) : 0.0;
    return vec2(mean, sum > 0.0 ? clamp(weightedU / sum, lo, hi) : uLight);
}

// Mesh visibility of light i over a particle's visible segment [lo, hi], as the fraction of the
// kernel's mass on the lit side. The reference integrates visibility along each ray, so a shadow
// boundary crossing a particle shades it by how much of its mass lies past the boundary: smooth
// from pixel to pixel, never a cut through the billboard (seed 001 §III asks for the same). Taps at
// both ends and the shading point; where they disagree, the crossing is found by bisection and the
// boundary treated as locally flat, so the lit fraction is an erf ratio.
float segmentVisibility(int i, vec3 origin, vec3 dir, Chord c, float radius, float lo, float hi, float u) {
    float softness = radius / 3.0;
    vec3 base = origin + dir * c.tClosest;
    float vLo = meshVisibilityTap(i, base + dir * lo, softness);
    float vMid = meshVisibilityTap(i, base + dir * u, softness);
    float vHi = meshVisibilityTap(i, base + dir * hi, softness);
    bool firstHalf = (vLo > 0.5) != (vMid > 0.5), secondHalf = (vMid > 0.5) != (vHi > 0.5);
    if (!firstHalf && !secondHalf) return (vLo + 4.0 * vMid + vHi) / 6.0;  // no boundary crossed: depth-soft only
    float a = firstHalf ? lo : u, b = firstHalf ? u : hi;
    bool litAtA = (firstHalf ? vLo : vMid) > 0.5;
    for (int step = 0; step < 6; ++step) {
        float m = 0.5 * (a + b);
        if ((meshVisibilityTap(i, base + dir * m, softness) > 0.5) == litAtA) a = m;
        else b = m;
    }
    float crossing = 0.5 * (a + b);
    float sk = sqrt(KERNEL_FALLOFF) / radius;
    float total = gaussianSegment(sk, lo, hi);
    if (!(total > 0.0)) return vMid;
    float before = gaussianSegment(sk, lo, crossing) / total;  // mass fraction in front of the crossing
    // Lit before the crossing when the segment starts lit; the far part may cross back (both halves).
    float lit = litAtA == (firstHalf ? vLo > 0.5 : vMid > 0.5) && firstHalf ? (vLo > 0.5 ? before : 1.0 - before)
                                                                            : (vHi > 0.5 ? 1.0 - before : before);
    return clamp(lit, 0.0, 1.0);
}

// The source of one particle's visible segment [lo, hi] of the ray, for compositing it as one layer:
// every light at the shading point u, except point and spot lights whose closest approach to the
// ray lies inside the segment, near it: their falloff is averaged over the kernel instead, and the
// rest (phase, shadows, slices) is taken where that falloff is centred.
vec3 segmentSource(vec3 origin, vec3 dir, Chord c, float radius, float lo, float hi, float u, GpuParticle particle) {
    vec3 p = origin + dir * (c.tClosest + u);
    vec3 scattered = frame.ambient.rgb;
    for (int i = 0; i < frame.counts.x; ++i) {
        float attenuation = -1.0;
        vec3 at = p;
        float atU = u;
        if (lights[i].direction.w > 0.5) {
            float uLight = dot(lights[i].position.xyz - origin, dir) - c.tClosest;
            if (uLight > lo && uLight < hi && distance(p, lights[i].position.xyz) < 2.0 * radius) {
                vec2 mean = kernelMeanAttenuation(origin, dir, c, radius, lo, hi, i);
                // The peak sits at optical depth v inside this particle's segment, so it is seen
                // through e^−v of the particle itself, where compositing assumes (1 − e^−τ)/τ.
                float tau = particle.albedoSigma.w * chordIntegral(c, radius, lo, hi);
                float v = particle.albedoSigma.w * chordIntegral(c, radius, lo, mean.y);
                attenuation = mean.x * (tau > 1e-4 ? exp(-v) * tau / oneMinusExpNeg(tau) : 1.0);
                at = origin + dir * (c.tClosest + mean.y);
                atU = mean.y;
            }
        }
        float visibility = lights[i].spot.z >= 0.0 ? segmentVisibility(i, origin, dir, c, radius, lo, hi, atU) : 1.0;
        scattered += scatteredLight(i, at, dir, particle, attenuation, visibility);
    }
    return particle.albedoSigma.rgb * scattered + particle.emissionG.rgb;
}

// segmentVisibility for a block's segment [t0, t1] of the ray, with the uniform density a block
// assumes (seed 000 §2.4): the lit fraction is the lit share of the segment's length.
float uniformSegmentVisibility(int i, vec3 origin, vec3 dir, float t0, float t1, float t, float softness) {
    float vLo = meshVisibilityTap(i, origin + dir * t0, softness);
    float vMid = meshVisibilityTap(i, origin + dir * t, softness);
    float vHi = meshVisibilityTap(i, origin + dir * t1, softness);
    bool firstHalf = (vLo > 0.5) != (vMid > 0.5), secondHalf = (vMid > 0.5) != (vHi > 0.5);
    if ((!firstHalf && !secondHalf) || !(t1 > t0)) return (vLo + 4.0 * vMid + vHi) / 6.0;
    float a = firstHalf ? t0 : t, b = firstHalf ? t : t1;
    bool litAtA = (firstHalf ? vLo : vMid) > 0.5;
    for (int step = 0; step < 6; ++step) {
        float m = 0.5 * (a + b);
        if ((meshVisibilityTap(i, origin + dir * m, softness) > 0.5) == litAtA) a = m;
        else b = m;
    }
    float before = (0.5 * (a + b) - t0) / (t1 - t0);  // share of the segment in front of the crossing
    return clamp(firstHalf ? (vLo > 0.5 ? before : 1.0 - before) : (vHi > 0.5 ? 1.0 - before : before), 0.0, 1.0);
}

// The source of a block's visible segment [t0, t1] (uniform density inside a block): every light
// at the shading point t, with the mesh visibility taken over the segment.
vec3 blockSegmentSource(vec3 origin, vec3 dir, float t0, float t1, float t, GpuParticle block) {
    vec3 p = origin + dir * t;
    vec3 scattered = frame.ambient.rgb;
    for (int i = 0; i < frame.counts.x; ++i) {
        float visibility = lights[i].spot.z >= 0.0 ? uniformSegmentVisibility(i, origin, dir, t0, t1, t, block.positionRadius.w / 3.0) : 1.0;
        scattered += scatteredLight(i, p, dir, block, -1.0, visibility);
    }
    return block.albedoSigma.rgb * scattered + block.emissionG.rgb;
}
