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
    vec4 clip = v.viewProjection * vec4(p, 1.0);
    if (clip.w <= 0.0) return 1.0;
    vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) return 1.0;
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

// Source radiance per unit optical depth at p for a particle seen along `viewDir`.
vec3 mediumSource(vec3 p, vec3 viewDir, GpuParticle particle) {
    vec3 albedo = particle.albedoSigma.rgb;
    float softness = particle.positionRadius.w / 3.0;
    vec3 scattered = frame.ambient.rgb;
    for (int i = 0; i < frame.counts.x; ++i) {
        LightSample s = sampleLight(i, p);
        if (all(lessThanEqual(s.irradiance, vec3(0.0)))) continue;
        // θ between the light's travel direction (−toLight) and the direction to the camera (−viewDir).
        float cosTheta = dot(s.toLight, viewDir);
        float phase = phaseValue(particle.extra.x, particle.emissionG.w, cosTheta);
        float visibility = mediumMeshVisibility(i, p, softness);
        if (visibility <= 0.0) continue;
        float transmittance = exp(-mediumOpticalDepth(i, p));
        scattered += phase * s.irradiance * (visibility * transmittance);
    }
    return albedo * scattered + particle.emissionG.rgb;
}
