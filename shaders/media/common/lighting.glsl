// Light arriving at a point inside the medium and scattered towards the camera (docs/design.md §2):
//   J = albedo · (Σ_l p(θ) E_l V_mesh T_l + L_amb) + emission      (per unit optical depth)
// T_l = exp(−τ) from the light slices; V_mesh from the mesh shadow map with the smooth weighting of
// Bass and Anderson §III (never a hard cut through a billboard). Needs common/frame, lights, light_views,
// transmittance, media/optics.
#include "media/common/mesh_shadow.glsl"
#include "media/common/lamp_neighbourhood.glsl"
#include "media/common/multiple_scattering.glsl"
#include "media/common/peak_orders.glsl"
#include "media/common/own_optical_depth.glsl"

// Bass and Anderson §III: instead of a lit/unlit test per pixel, compare the occluder depth the shadow map
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
            float occluder = shadowTexelDepth(v, texture(uShadowDepth, vec3(shadowLayerUv(v, tapUv), v.params2.x)).r);
            lit += 0.5 * (1.0 + erfApprox((occluder - receiver) / width));
        }
    }
    return lit / 9.0;
}

// After meshVisibilityTap, which the lamp integration uses per node.
#include "media/common/local_light_segment.glsl"

// Light i scattered towards the camera at p, per unit optical depth and albedo: p(θ) E V T, all
// taken at p. `visibility` ≥ 0 replaces the mesh visibility at p (see segmentVisibility),
// `transmittance` ≥ 0 the medium's e^−τ towards the light at p (see layerLightTransmittance).
vec3 scatteredLight(int i, vec3 p, vec3 viewDir, GpuParticle particle, float visibility, float transmittance) {
    LightSample s = sampleLight(i, p);
    if (all(lessThanEqual(s.irradiance, vec3(0.0)))) return vec3(0.0);
    if (visibility < 0.0) visibility = mediumMeshVisibility(i, p, particle.positionRadius.w / 3.0);
    if (visibility <= 0.0) return vec3(0.0);
    if (transmittance < 0.0) transmittance = exp(-mediumOpticalDepth(i, p));
    // θ between the light's travel direction (−toLight) and the direction to the camera (−viewDir).
    float phase = litPhase(particle.extra.x, particle.emissionG.w, luminance(particle.albedoSigma.rgb), transmittance, s.toLight, viewDir);
    return phase * s.irradiance * (visibility * transmittance);
}

// The scattering source of the environment at p per unit albedo, seen along viewDir: unshadowed
// ambient, or in the multiple model the grid's environment and light scattered more than once.
vec3 ambientSource(vec3 p, vec3 viewDir, GpuParticle particle) {
#ifdef MEDIA_MULTIPLE
    return multipleSource(p, viewDir, particle.emissionG.w);
#else
    return frame.ambient.rgb;
#endif
}

// ∫₀^τ e^−τl(v) e^−v dv / (1 − e^−τ) for τl linear in v through `entry` at v = 0 and `atShading`
// at v = vBar (see layerLightTransmittance), kept ≥ 0 across the layer.
float layerTransmittance(float entry, float atShading, float vBar, float tau) {
    float a = entry;
    float b = max((atShading - a) / vBar, -a / tau);  // τl stays ≥ 0 across the layer
    float k = 1.0 + b, kT = k * tau;
    float integral;  // ∫₀^τ e^−(a + b v) e^−v dv
    if (abs(kT) < 1e-3) integral = exp(-a) * tau * (1.0 - kT * (0.5 - kT / 6.0));
    else if (k > 0.0) integral = exp(-a) * oneMinusExpNeg(kT) / k;
    else integral = exp(-(a + kT)) * oneMinusExpNeg(-kT) / -k;  // a + kT = τl at the back + τ ≥ 0
    return integral / oneMinusExpNeg(tau);
}

// The medium's transmittance towards light i as a whole layer receives it. The layer adds
// ∫₀^τ J(v) e^−v dv (v: its optical depth from `entry`, where the ray enters it), and J carries
// e^−τl(v), τl the light's optical depth; one e^−τl at the shading point v̄ (Jensen's gap) misses
// how τl changes across a dense layer: seen along the sun from inside a dense particle, τl falls
// as v grows and every point sends the same light; a thick particle lit from the side is a
// half-space whose surface sends μ0/(μ0 + μ) of it. With τl linear in v through its values at the
// entry and at v̄, the integral is closed-form and exact in both; returns it over 1 − e^−τ, in
// place of e^−τl(v̄). τl carries the particle's own optical depth exactly where the slices do not
// resolve it (particleLightDepth): their spread of it distorts the slope across a small particle.
float layerLightTransmittance(int i, vec3 entry, vec3 p, float vBar, float tau, GpuParticle particle) {
    float atP = particleLightDepth(i, p, particle);
    if (!(vBar > 1e-4) || !(tau > 1e-4)) return exp(-atP);
    return layerTransmittance(particleLightDepth(i, entry, particle), atP, vBar, tau);
}

// Where a mesh shadow boundary crosses the ray between t0 and t1: taps at both ends and at t; where
// two disagree, bisection between them, then one secant step on the taps' depth margins, which is
// exact where the occluder is locally flat (bisection alone leaves the crossing up to 1/128 of the
// segment off, which a sharp phase peak shows). False when none disagree, with `soft` 1 (all lit)
// or 0; else the crossing and whether the ray is lit in front of it.
// Not the taps' depth-soft average: a ray that stays on one side is wholly lit or wholly shadowed in
// the reference, and the average dims rays that graze a surface.
bool meshShadowCrossing(int i, vec3 origin, vec3 dir, float t0, float t, float t1, out float soft, out float crossing,
                        out bool litInFront) {
    float m0 = meshShadowMargin(i, origin + dir * t0), mt = meshShadowMargin(i, origin + dir * t);
    float m1 = meshShadowMargin(i, origin + dir * t1);
    bool lo = m0 > 0.0, mid = mt > 0.0, hi = m1 > 0.0;
    soft = mid ? 1.0 : 0.0;  // what it is when all three taps agree
    crossing = t;
    bool firstHalf = lo != mid, secondHalf = mid != hi;
    litInFront = firstHalf ? lo : mid;
    if ((!firstHalf && !secondHalf) || !(t1 > t0)) return false;  // no boundary crossed
    float a = firstHalf ? t0 : t, b = firstHalf ? t : t1;
    float ma = firstHalf ? m0 : mt, mb = firstHalf ? mt : m1;
    for (int step = 0; step < 6; ++step) {
        float m = 0.5 * (a + b);
        float mm = meshShadowMargin(i, origin + dir * m);
        if ((mm > 0.0) == litInFront) {
            a = m;
            ma = mm;
        } else {
            b = m;
            mb = mm;
        }
    }
    // ma and mb have opposite signs, so the secant's root lies in [a, b] (a margin of 1e30 where
    // nothing casts only pushes it to that end).
    float w = ma / (ma - mb);
    crossing = a + (b - a) * clamp(w, 0.0, 1.0);
    return true;
}

// Mesh visibility of light i over a particle's visible segment [lo, hi], as the fraction of the
// kernel's mass on the lit side. The reference integrates visibility along each ray, so a shadow
// boundary crossing a particle shades it by how much of its mass lies past the boundary: smooth
// from pixel to pixel, never a cut through the billboard (Bass and Anderson §III asks for the same). Taps at
// both ends and the shading point; where they disagree, the crossing is found by bisection and the
// boundary treated as locally flat, so the lit fraction is an erf ratio.
float segmentVisibility(int i, vec3 origin, vec3 dir, Chord c, float radius, float lo, float hi, float u) {
    float soft, crossing;
    bool litInFront;
    vec3 base = origin + dir * c.tClosest;
    if (!meshShadowCrossing(i, base, dir, lo, u, hi, soft, crossing, litInFront)) return soft;
    float sk = sqrt(KERNEL_FALLOFF) / radius;
    float total = gaussianSegment(sk, lo, hi);
    if (!(total > 0.0)) return soft;
    float before = gaussianSegment(sk, lo, crossing) / total;  // mass fraction in front of the crossing
    return clamp(litInFront ? before : 1.0 - before, 0.0, 1.0);
}

// The source of one particle's visible segment [lo, hi] of the ray, for compositing it as one layer:
// every light at the shading point u, except point and spot lights that vary across the segment:
// the lamp's closest approach lies inside it, near the particle, or a spot cone's edge crosses it.
// Those are integrated over the segment (local_light_segment.glsl), their mesh shadow taken where
// the integrand is centred, and near the lamp their attenuation by the other layers made exact.
// `tau`: the segment's optical depth, for the light's transmittance integrated over it
// (layerLightTransmittance) in the MEDIA_LAYER_LIGHT build; without it, that is taken at u
// (particle_pass.cpp: llvmpipe runs both sides of a branch, so a switch must be a build).
vec3 segmentSource(vec3 origin, vec3 dir, Chord c, float radius, float lo, float hi, float u, float tau,
                   GpuParticle particle, LayerOrder layer) {
    vec3 p = origin + dir * (c.tClosest + u);
    vec3 entry = origin + dir * (c.tClosest + lo);
    float vBar = shadingDepthFraction(tau) * tau;
    vec3 scattered = ambientSource(p, dir, particle);
    int i = 0;
    if (frame.counts.x > 0) do {  // not for: llvmpipe runs a for loop's body once more, masked
#ifdef SEGMENT_SKIPS_LIGHT  // particle_lighting.comp: lights its fragments evaluate
        if (SEGMENT_SKIPS_LIGHT(i)) continue;
#endif
#ifdef MEDIA_LOCAL_LIGHTS  // particle_pass.cpp builds this only for frames with point or spot lights
        if (lights[i].direction.w > 0.5) {
            vec2 lit = spotConeInterval(i, origin, dir, c, lo, hi);
            if (!(lit.y > lit.x)) continue;  // the ray misses the cone inside this particle
            // Near: the lamp lies closer to the segment than the kernel's size, so 1/d² varies across it.
            float uNearest = clamp(dot(lights[i].position.xyz - origin, dir) - c.tClosest, lo, hi);
            bool nearLamp = distance(origin + dir * (c.tClosest + uNearest), lights[i].position.xyz) < 2.0 * radius;
            if (nearLamp || lit.x > lo || lit.y < hi) {
                vec2 J = localLightSegment(origin, dir, c, radius, lo, hi, lit, i, particle, nearLamp, layer);
                if (J.x <= 0.0) continue;
                // The depth softness stands for the mass around a tap; here the light comes from
                // within about the lamp's distance of J.y, not from the whole kernel (R/3 darkens the
                // medium above a lit floor around a lamp inside a particle).
                float visibility = lights[i].spot.z >= 0.0 && !nearLamp ? segmentVisibility(i, origin, dir, c, radius, lo, hi, J.y) : 1.0;
                float transmittance = nearLamp ? 1.0 : exp(-particleLightDepth(i, origin + dir * (c.tClosest + J.y), particle));
                scattered += lights[i].radiance.rgb * (J.x * visibility * transmittance);
                continue;
            }
        }
#endif
        float visibility = lights[i].spot.z >= 0.0 ? segmentVisibility(i, origin, dir, c, radius, lo, hi, u) : 1.0;
#ifdef MEDIA_LAYER_LIGHT
        float transmittance = layerLightTransmittance(i, entry, p, vBar, tau, particle);
#else
        float transmittance = exp(-particleLightDepth(i, p, particle));
#endif
        scattered += scatteredLight(i, p, dir, particle, visibility, transmittance);
    } while (++i < frame.counts.x);
    return particle.albedoSigma.rgb * scattered + particle.emissionG.rgb;
}
