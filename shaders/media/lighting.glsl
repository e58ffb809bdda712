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
// A 3×3 neighbourhood adds lateral softness. 1 = fully lit.
float mediumMeshVisibility(int lightIndex, vec3 p, float softness) {
    GpuLight L = lights[lightIndex];
    int first = int(L.spot.z);
    if (first < 0) return 1.0;
    GpuLightView v = shadowViews[lightViewIndex(first, int(L.spot.w), L.position.xyz, p)];
    vec2 uv;
    if (!lightViewUv(v, p, uv)) return 1.0;  // outside the shadow map: nothing casts there
    float receiver = -(v.view * vec4(p, 1.0)).z;
    float texel = 1.0 / float(frame.counts.z);
    float width = max(softness, 1e-4) * 1.41421356;
    float lit = 0.0;
    for (int y = -1; y <= 1; ++y) {
        for (int x = -1; x <= 1; ++x) {
            float stored = texture(uShadowDepth, vec3(uv + vec2(x, y) * texel, v.params2.x)).r;
            float occluder = shadowTexelDepth(v, stored);
            lit += 0.5 * (1.0 + erfApprox((occluder - receiver) / width));
        }
    }
    return lit / 9.0;
}

// Light i scattered towards the camera at p, per unit optical depth and albedo: p(θ) E V T.
// `inverseSquare` > 0 replaces the point/spot light's 1/d² at p (see kernelMeanInverseSquare).
vec3 scatteredLight(int i, vec3 p, vec3 viewDir, GpuParticle particle, float inverseSquare) {
    LightSample s = sampleLight(i, p);
    if (all(lessThanEqual(s.irradiance, vec3(0.0)))) return vec3(0.0);
    vec3 irradiance = inverseSquare > 0.0 ? s.irradiance * (s.distance * s.distance * inverseSquare) : s.irradiance;
    // θ between the light's travel direction (−toLight) and the direction to the camera (−viewDir).
    float phase = phaseValue(particle.extra.x, particle.emissionG.w, dot(s.toLight, viewDir));
    float visibility = mediumMeshVisibility(i, p, particle.positionRadius.w / 3.0);
    if (visibility <= 0.0) return vec3(0.0);
    return phase * irradiance * (visibility * exp(-mediumOpticalDepth(i, p)));
}

// Source radiance per unit optical depth at p for a particle seen along `viewDir`:
// albedo · (Σ p E V T + L_amb) + emission.
vec3 mediumSource(vec3 p, vec3 viewDir, GpuParticle particle) {
    vec3 scattered = frame.ambient.rgb;
    for (int i = 0; i < frame.counts.x; ++i) scattered += scatteredLight(i, p, viewDir, particle, 0.0);
    return particle.albedoSigma.rgb * scattered + particle.emissionG.rgb;
}

// The kernel-weighted mean of 1/d² from a light at `light` along the segment [lo, hi] (u measured
// from the chord's closest point). Near a point light 1/d² peaks far more sharply than the kernel
// varies, so one sample is badly wrong; with u = u_l + b·tan φ the integral ∫ρ/d² du becomes
// (1/b)∫ρ dφ, smooth in φ, which six Gauss–Legendre points integrate well.
float kernelMeanInverseSquare(vec3 origin, vec3 dir, Chord c, float radius, float lo, float hi, vec3 light) {
    vec3 toLight = light - origin;
    float tLight = dot(toLight, dir);
    float b = max(length(toLight - tLight * dir), 1e-4 * radius);
    float uLight = tLight - c.tClosest;
    float phi0 = atan((lo - uLight) / b), phi1 = atan((hi - uLight) / b);
    float k = KERNEL_FALLOFF / (radius * radius);
    const float nodes[3] = float[](0.2386191861, 0.6612093865, 0.9324695142);
    const float weights[3] = float[](0.4679139346, 0.3607615730, 0.1713244924);
    float mid = 0.5 * (phi0 + phi1), half_ = 0.5 * (phi1 - phi0), sum = 0.0;
    for (int j = 0; j < 3; ++j) {
        for (int sgn = -1; sgn <= 1; sgn += 2) {
            float u = uLight + b * tan(mid + float(sgn) * half_ * nodes[j]);
            sum += weights[j] * exp(-k * u * u);
        }
    }
    float sk = sqrt(k);
    float mass = (HALF_SQRT_PI / sk) * (erfApprox(sk * hi) - erfApprox(sk * lo));
    return mass > 0.0 ? half_ * sum / (b * mass) : 0.0;
}

// The source of one particle's visible segment [lo, hi] of the ray, for compositing it as one layer:
// every light at the shading point u, except point and spot lights whose closest approach to the
// ray lies inside the segment, whose 1/d² is averaged over the kernel instead.
vec3 segmentSource(vec3 origin, vec3 dir, Chord c, float radius, float lo, float hi, float u, GpuParticle particle) {
    vec3 p = origin + dir * (c.tClosest + u);
    vec3 scattered = frame.ambient.rgb;
    for (int i = 0; i < frame.counts.x; ++i) {
        float inverseSquare = 0.0;
        vec3 at = p;
        if (lights[i].direction.w > 0.5) {
            float uLight = dot(lights[i].position.xyz - origin, dir) - c.tClosest;
            if (uLight > lo && uLight < hi && distance(at, lights[i].position.xyz) < 2.0 * radius) {
                inverseSquare = kernelMeanInverseSquare(origin, dir, c, radius, lo, hi, lights[i].position.xyz);
                at = origin + dir * (c.tClosest + uLight);  // the rest (cone, shadows, phase) where the light is nearest
            }
        }
        scattered += scatteredLight(i, at, dir, particle, inverseSquare);
    }
    return particle.albedoSigma.rgb * scattered + particle.emissionG.rgb;
}
