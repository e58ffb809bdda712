#version 450 core
// Fast particles: per fragment the kernel's optical depth along the pixel's ray, clipped at the
// opaque surface (and at the eye with MEDIA_EYE_INSIDE), from the pre-integrated kernel
// table (the sheet-buffer splatting paper); the source from the lighting pass's fit (particle_lighting.comp),
// with the sun's phase function and the lamps (MEDIA_FRAGMENT_LAMPS) at this pixel's own ray. Output (α·J, α)
// blends premultiplied, exactly as particles.frag's does.
#include "media/bindings.glsl"
#include "common/math.glsl"
#include "common/frame.glsl"
#include "common/lights.glsl"
#include "media/common/optics.glsl"
#include "media/common/kernel_table.glsl"
#include "media/common/particle_light_layout.glsl"
#ifdef MEDIA_FRAGMENT_LAMPS
#include "common/light_views.glsl"
#include "media/common/slices.glsl"
#include "media/common/spot_cone.glsl"
#include "media/common/mesh_shadow.glsl"
#endif

layout(binding = MEDIA_SCENE_DEPTH_UNIT) uniform sampler2D uSceneDepth;
layout(location = 1) uniform vec2 uFullResScale;

flat in vec4 vCentreRadius;
flat in float vSigma;
flat in float vFog;  // the fog factor at the centre (common/fog.glsl)
#ifdef SPLAT_CONSTANT
flat in vec4 vSource;
#else
in vec4 vSource;
in vec2 vCorner;
flat in vec4 vFit[4];
#endif
flat in vec4 vSun;
flat in vec2 vPhase;
#ifdef MEDIA_FRAGMENT_LAMPS
flat in vec3 vAlbedo;

// Lamp `light`'s light scattered by the particle's visible segment [lo, hi] of the ray (u from the
// closest point), per unit albedo and radiance, as the layer's source: σ∫ρ(u)e^−τ(u)·S(u)du / α
// with τ(u) the particle's own optical depth in front of u and S = shape·phase·V·T/d² (V the mesh
// shadow map's visibility, T the slices' transmittance from the lamp). Where the ray passes the lamp within two deviations, 1/d²
// peaks far more sharply than the kernel varies: LAMP_NODES Gauss–Legendre nodes in φ over the
// part inside a spot's cone, u = u_l + b·tan φ (u_l the lamp's closest approach, b its distance),
// as local_light_segment.glsl does with more, each with its own T and e^−τ (inside a dense
// particle both fall steeply away from the lamp). Elsewhere S varies slowly and is taken at the
// shading point p.
const int LAMP_NODES = 6;
const float kLampNodes[6] = float[](-0.9324695142, -0.6612093865, -0.2386191861, 0.2386191861, 0.6612093865, 0.9324695142);
const float kLampWeights[6] = float[](0.1713244924, 0.3607615730, 0.4679139346, 0.4679139346, 0.3607615730, 0.1713244924);

float lampSource(int light, vec3 origin, vec3 dir, float tc, float lo, float hi, float beta, float alpha, vec3 p) {
    float radius = vCentreRadius.w;
    vec2 lit = spotConeInterval(light, origin, dir, Chord(tc, 0.0, 0.0), lo, hi);
    if (!(lit.y > lit.x)) return 0.0;
    vec3 lamp = lights[light].position.xyz;
    vec3 toLamp = lamp - origin;
    float uLamp = dot(toLamp, dir) - tc;
    float s = radius / 3.0;
    float b = max(length(toLamp - (uLamp + tc) * dir), 1e-4 * radius);
    bool near = b < 2.0 * s && uLamp > lo - 2.0 * s && uLamp < hi + 2.0 * s && alpha > 0.0;
    float phi0 = atan((lit.x - uLamp) / b), phi1 = atan((lit.y - uLamp) / b);
    float mid = 0.5 * (phi0 + phi1), half_ = 0.5 * (phi1 - phi0);
    float k = KERNEL_FALLOFF / (radius * radius), sum = 0.0;
    float entry = kernelSegment(beta, lo / radius);
    // A loop, so llvmpipe leaves it after one pass where no lane is near (an if runs under a mask
    // whatever the lanes); do-while, as a for loop's test costs one more masked pass.
    int j = 0;
    do {
        float u = uLamp + b * tan(mid + half_ * kLampNodes[j]);
        vec3 x = origin + dir * (tc + u);
        float phase = phaseValue(vPhase.x, vPhase.y, normalize(lamp - x), dir);
        float inFront = vSigma * radius * max(kernelSegment(beta, u / radius) - entry, 0.0);
        // Near the lamp its light comes from within about its distance, not from the whole kernel.
        float visibility = lights[light].spot.z >= 0.0 ? meshVisibilityTap(light, x, 0.1 * distance(x, lamp)) : 1.0;
        sum += kLampWeights[j] * exp(-k * u * u - inFront - mediumOpticalDepth(light, x)) * phase * lightShape(light, x) * visibility;
    } while (++j < (near ? LAMP_NODES : 0));  // sum is read only where near
    if (near) return vSigma * exp(-k * (radius * radius * beta * beta)) * sum * half_ / (b * alpha);
    vec3 toP = lamp - p;
    float d2 = max(dot(toP, toP), 1e-12);
    float visibility = lights[light].spot.z >= 0.0 ? meshVisibilityTap(light, p, radius / 3.0) : 1.0;
    return lightShape(light, p) * phaseValue(vPhase.x, vPhase.y, toP * inversesqrt(d2), dir) * exp(-mediumOpticalDepth(light, p)) * visibility / d2;
}
#endif

layout(location = 0) out vec4 outColor;

void main() {
    vec2 fragCoord = gl_FragCoord.xy * uFullResScale;
    vec3 origin, dir;
    cameraRay(fragCoord, origin, dir);
    vec3 oc = vCentreRadius.xyz - origin;
    float tc = dot(oc, dir);
    vec3 perp = oc - tc * dir;
    float radius = vCentreRadius.w, invRadius = 1.0 / radius;
    float beta2 = dot(perp, perp) * invRadius * invRadius;
    float beta = sqrt(beta2);
    float depth = linearViewDepth(texelFetch(uSceneDepth, ivec2(fragCoord), 0).r);
    float tSurface = frameOrthographic() ? depth : depth / dot(dir, frame.cameraForward.xyz);
    float segment = kernelSegment(beta, (tSurface - tc) * invRadius);
#ifdef MEDIA_EYE_INSIDE
    segment -= kernelSegment(beta, -tc * invRadius);
#endif
    float alpha = oneMinusExpNeg(vSigma * radius * max(segment, 0.0));
#ifdef SPLAT_CONSTANT
    vec4 fit = vSource;
#else
    vec4 fit = vSource + (vFit[0] + vFit[1] * beta2) * beta2 + vFit[2] * (vCorner.x * vCorner.x * vCorner.x) +
               vFit[3] * (vCorner.y * vCorner.y * vCorner.y);
#endif
    vec3 source = max(fit.rgb, vec3(0.0));
    if (uFragmentSun >= 0)  // the sun's phase at this pixel's own ray: g = 0.99 peaks within a few pixels
        source += vSun.rgb * (phaseValue(vPhase.x, vPhase.y, -lights[uFragmentSun].direction.xyz, dir) * max(fit.a, 0.0));
#ifdef MEDIA_FRAGMENT_LAMPS
    float h = sqrt(max(radius * radius - dot(perp, perp), 0.0));
    float lo = max(-h, -tc), hi = min(h, tSurface - tc);
    vec3 p = origin + dir * (tc - vSun.a);
    // The lamps are listed first (this variant has at least one): as many passes as lamps.
    int k = 0;
    do {
        int light = uFragmentLamps[k];
        source += vAlbedo * lights[light].radiance.rgb * lampSource(light, origin, dir, tc, lo, hi, beta, alpha, p);
    } while (++k < MAX_FRAGMENT_LAMPS && uFragmentLamps[min(k, MAX_FRAGMENT_LAMPS - 1)] >= 0);
#endif
    source = mix(frame.fogColor.rgb, source, vFog);
    outColor = vec4(source * alpha, alpha);
}
