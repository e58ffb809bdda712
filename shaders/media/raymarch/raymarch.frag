#version 450 core
// Raymarch mode (after Jendersie, raymarch/raymarch_pass.cpp): the voxel grid marched per texel of the
// media target. Samples sit a voxel apart, the first at a per-pixel jittered offset (fine noise,
// no banding); the march stops at the scene depth (a mesh inside the cloud needs no special case)
// and once the view transmittance is below 1e-3. Each sample is lit as lighting.glsl lights a
// particle: every light with its slices' transmittance and one mesh-shadow tap, plus ambient and
// emission. Output: (in-scattered radiance, view transmittance), written, not blended.
#include "media/bindings.glsl"
#include "common/math.glsl"
#include "common/frame.glsl"
#include "common/fog.glsl"
#include "common/lights.glsl"
#include "common/light_views.glsl"
#include "media/common/slices.glsl"
#include "media/common/optics.glsl"
#include "media/common/mesh_shadow.glsl"
#include "media/common/multiple_scattering.glsl"
#include "media/common/peak_orders.glsl"

layout(binding = MEDIA_SCENE_DEPTH_UNIT) uniform sampler2D uSceneDepth;
layout(binding = MEDIA_VOXEL_SCATTERING_UNIT) uniform sampler3D uScattering;  // rgb σ_t·albedo, a σ_t
layout(binding = MEDIA_VOXEL_EMISSION_UNIT) uniform sampler3D uEmission;      // rgb σ_t·emission, a σ_t·g
layout(location = 1) uniform vec2 uFullResScale;  // full-resolution pixels per target texel
layout(location = 7) uniform vec2 uFragOffset;    // the target's first pixel in the viewport (0 but for a rect of edges)
layout(location = 2) uniform vec3 uGridCorner;    // frame-relative
layout(location = 3) uniform vec3 uGridExtent;
layout(location = 4) uniform float uVoxel;
layout(location = 5) uniform int uMaxSteps;
layout(location = 6) uniform int uRayleigh;

layout(location = 0) out vec4 outColor;

// Interleaved gradient noise (Jimenez 2014): a start offset in [0, 1) per pixel.
float jitter(vec2 p) { return fract(52.9829189 * fract(dot(p, vec2(0.06711056, 0.00583715)))); }

// The ray's interval inside the grid; zero direction components become tiny ones, so a ray along
// an axis gets ±infinity slabs instead of NaN.
vec2 gridInterval(vec3 origin, vec3 dir) {
    vec3 d = mix(dir, vec3(1e-30), lessThan(abs(dir), vec3(1e-30)));
    vec3 t0 = (uGridCorner - origin) / d, t1 = (uGridCorner + uGridExtent - origin) / d;
    vec3 lo = min(t0, t1), hi = max(t0, t1);
    return vec2(max(max(lo.x, lo.y), max(lo.z, 0.0)), min(min(hi.x, hi.y), hi.z));
}

// Σ_l p(θ) E_l V_mesh T_l at p, per unit albedo (lighting.glsl's scatteredLight for a voxel).
vec3 lightAt(vec3 p, vec3 dir, float g, float albedo) {
    vec3 sum = vec3(0.0);
    int i = 0;
    if (frame.counts.x > 0) do {  // not for: llvmpipe runs a for loop's body once more, masked
        LightSample s = sampleLight(i, p);
        float transmittance = exp(-mediumOpticalDepth(i, p));
        float phase = litPhase(float(uRayleigh), g, albedo, transmittance, s.toLight, dir);
        sum += phase * s.irradiance * (meshVisibilityTap(i, p, uVoxel) * transmittance);
    } while (++i < frame.counts.x);
    return sum;
}

// The environment's source at p per unit albedo seen along dir: unshadowed ambient, or the
// multiple model's grid.
vec3 ambientAt(vec3 p, vec3 dir, float g) {
#ifdef MEDIA_MULTIPLE
    return multipleSource(p, dir, g);
#else
    return frame.ambient.rgb;
#endif
}

void main() {
    vec2 fragCoord = gl_FragCoord.xy * uFullResScale + uFragOffset;
    vec3 origin, dir;
    cameraRay(fragCoord, origin, dir);
    float sceneDepth = linearViewDepth(texelFetch(uSceneDepth, ivec2(fragCoord), 0).r);
    float tSurface = rayDistanceAtViewDepth(dir, sceneDepth);
    vec2 span = gridInterval(origin, dir);
    span.y = min(span.y, tSurface);
    if (!(span.y > span.x)) {
        outColor = vec4(0.0, 0.0, 0.0, 1.0);
        return;
    }
    int steps = clamp(int(ceil((span.y - span.x) / uVoxel)), 1, uMaxSteps);
    float dt = (span.y - span.x) / float(steps);
    float t = span.x + dt * jitter(gl_FragCoord.xy + uFragOffset);
    vec3 radiance = vec3(0.0);
    float transmittance = 1.0;
    for (int k = 0; k < steps && transmittance > 1e-3; ++k, t += dt) {
        vec3 p = origin + dir * t;
        vec3 uvw = (p - uGridCorner) / uGridExtent;
        vec4 a = texture(uScattering, uvw);
        if (!(a.w > 0.0)) continue;
        vec4 e = texture(uEmission, uvw);
        float g = clamp(e.w / a.w, -0.999, 0.999);
        vec3 source = (a.rgb * (lightAt(p, dir, g, luminance(a.rgb) / a.w) + ambientAt(p, dir, g)) + e.rgb) / a.w;  // J per unit optical depth
        float alpha = oneMinusExpNeg(a.w * dt);
        radiance += transmittance * alpha * source;
        transmittance *= 1.0 - alpha;
    }
    // Fog once per pixel, at the middle of the medium's span (the particle modes take it per particle).
    float f = fogEnabled() ? fogFactor(origin, dir, 0.5 * (span.x + span.y)) : 1.0;
    outColor = vec4(f * radiance + (1.0 - f) * (1.0 - transmittance) * frame.fogColor.rgb, transmittance);
}
