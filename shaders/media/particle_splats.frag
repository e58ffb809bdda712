#version 450 core
// Fast particles: per fragment only the kernel's optical depth along the pixel's ray, clipped at
// the opaque surface (and at the eye with MEDIA_EYE_INSIDE), from seed 004's pre-integrated kernel
// table; the source comes interpolated from the vertices. Output (α·J, α) blends premultiplied,
// exactly as particles.frag's does.
#include "common/math.glsl"
#include "common/frame.glsl"
#include "media/kernel_table.glsl"
#ifdef MEDIA_FRAGMENT_LAMPS
#include "common/lights.glsl"
#include "common/light_views.glsl"
#include "common/transmittance.glsl"
#include "media/optics.glsl"
#include "media/particle_light_layout.glsl"
#endif

layout(binding = 3) uniform sampler2D uSceneDepth;
layout(location = 1) uniform vec2 uFullResScale;

flat in vec4 vCentreRadius;
flat in float vSigma;
in vec3 vSource;
flat in vec3 vRadial;
flat in vec3 vQuartic, vCubicX, vCubicY;
in vec2 vCorner;
#ifdef MEDIA_FRAGMENT_LAMPS
flat in vec3 vLampFactor[MAX_FRAGMENT_LAMPS];
flat in vec3 vPhase;

// Lamp `light`'s 1/d², shape and phase averaged over the kernel's mass along the visible segment
// [lo, hi] of the ray (u from the closest point). Where the ray passes the lamp within two
// deviations, 1/d² peaks far more sharply than the kernel varies: four Gauss–Legendre nodes in
// φ, u = u_l + b·tan φ (u_l the lamp's closest approach, b its distance), as
// local_light_segment.glsl does with more; elsewhere one point, the shading point p.
float lampKernelMean(int light, vec3 origin, vec3 dir, float tc, float lo, float hi, float radius, float b2, float mass, vec3 p) {
    vec3 lamp = lights[light].position.xyz;
    vec3 toLamp = lamp - origin;
    float uLamp = dot(toLamp, dir) - tc;
    float s = radius / 3.0;
    float b = max(length(toLamp - (uLamp + tc) * dir), 1e-4 * radius);
    bool near = b < 2.0 * s && uLamp > lo - 2.0 * s && uLamp < hi + 2.0 * s && mass > 0.0;
    const float nodes[4] = float[](-0.8611363116, -0.3399810436, 0.3399810436, 0.8611363116);
    const float weights[4] = float[](0.3478548451, 0.6521451549, 0.6521451549, 0.3478548451);
    float phi0 = atan((lo - uLamp) / b), phi1 = atan((hi - uLamp) / b);
    float mid = 0.5 * (phi0 + phi1), half_ = 0.5 * (phi1 - phi0);
    float k = KERNEL_FALLOFF / (radius * radius), sum = 0.0;
    for (int j = 0; j < (near ? 4 : 0); ++j) {  // a loop, so llvmpipe skips it where no lane is near
        float u = uLamp + b * tan(mid + half_ * nodes[j]);
        vec3 x = origin + dir * (tc + u);
        float phase = phaseValue(vPhase.x, vPhase.y, normalize(lamp - x), dir);
        sum += weights[j] * exp(-k * (b2 + u * u)) * phase * lightShape(light, x);
    }
    if (near) return sum * half_ / (b * mass);
    vec3 toP = lamp - p;
    float d2 = max(dot(toP, toP), 1e-12);
    return lightShape(light, p) * phaseValue(vPhase.x, vPhase.y, toP * inversesqrt(d2), dir) / d2;
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
    float invRadius = 1.0 / vCentreRadius.w;
    float beta2 = dot(perp, perp) * invRadius * invRadius;
    float beta = sqrt(beta2);
    float depth = linearViewDepth(texelFetch(uSceneDepth, ivec2(fragCoord), 0).r);
    float tSurface = frameOrthographic() ? depth : depth / dot(dir, frame.cameraForward.xyz);
    float segment = kernelSegment(beta, (tSurface - tc) * invRadius);
#ifdef MEDIA_EYE_INSIDE
    segment -= kernelSegment(beta, -tc * invRadius);
#endif
    float alpha = oneMinusExpNeg(vSigma * vCentreRadius.w * max(segment, 0.0));
    vec3 source = max(vSource + (vRadial + vQuartic * beta2) * beta2 + vCubicX * (vCorner.x * vCorner.x * vCorner.x) + vCubicY * (vCorner.y * vCorner.y * vCorner.y), vec3(0.0));
#ifdef MEDIA_FRAGMENT_LAMPS
    float radius = vCentreRadius.w;
    float h = sqrt(max(radius * radius - dot(perp, perp), 0.0));
    float lo = max(-h, -tc), hi = min(h, tSurface - tc);
    float mass = radius * max(segment, 0.0);  // ∫ρ du over [lo, hi]
    vec3 p = origin + dir * (tc - vPhase.z);
    for (int k = 0; k < MAX_FRAGMENT_LAMPS; ++k) {
        int light = uFragmentLamps[k];
        if (light < 0) continue;
        float mean = lampKernelMean(light, origin, dir, tc, lo, hi, radius, dot(perp, perp), mass, p);
        source += vLampFactor[k] * lights[light].radiance.rgb * (mean * exp(-mediumOpticalDepth(light, p)));
    }
#endif
    outColor = vec4(source * alpha, alpha);
}
