#version 450 core
// Light slices (docs/design.md §3): for the light ray through this texel, the particle's optical depth
// from the light up to each slice plane, in closed form, added into 4 slices per RGBA32F target.
// Additive blending: no sort, and the order particles arrive in cannot change the result.
#include "common/math.glsl"
#include "media/common/optics.glsl"
#include "media/common/particle_data.glsl"
#include "media/common/view_rays.glsl"

layout(location = 0) uniform mat4 uView;
layout(location = 2) uniform vec4 uParams;              // x: perspective, y: depth near, z: depth far, w: slices
layout(location = 3) uniform vec2 uHalfExtent;  // tan of the half angles, or half size in metres (view_rays.glsl)
layout(location = 4) uniform vec2 uViewportSize;
layout(location = 6) uniform vec3 uLightOrigin;  // origin-relative light position (perspective views)

flat in int vParticle;

layout(location = 0) out vec4 outSlices[8];

void main() {
    GpuParticle particle = particles[vParticle];
    vec2 ndc = gl_FragCoord.xy / uViewportSize * 2.0 - 1.0;
    vec3 origin, dir;
    viewRay(ndc, uHalfExtent, uView, uParams.x > 0.5, uLightOrigin, origin, dir);
    vec3 axis = -vec3(uView[0][2], uView[1][2], uView[2][2]);  // light view −Z in world space
    float cosAxis = uParams.x > 0.5 ? max(dot(dir, axis), 1e-6) : 1.0;
    Chord chord = chordOf(origin, dir, particle.positionRadius.xyz, particle.positionRadius.w);
    if (chord.halfChord <= 0.0) discard;

    float radius = particle.positionRadius.w;
    float k = KERNEL_FALLOFF / (radius * radius);
    float sk = sqrt(k);
    float scale = particle.albedoSigma.w * exp(-k * chord.b2) * (HALF_SQRT_PI / sk);
    // A perspective view's rays start at the light: a light inside the sphere sees only the part ahead.
    float start = uParams.x > 0.5 ? max(-chord.halfChord, -chord.tClosest) : -chord.halfChord;
    // The sphere wholly behind the light along this ray (the view covers everything for a sphere
    // beside the light): nothing lies ahead, and the erf difference below would be negative.
    if (start >= chord.halfChord) discard;
    float entry = erfApprox(sk * start);

    int slices = int(uParams.w);
    float spacing = (uParams.z - uParams.y) / uParams.w;
    vec4 values[8] = vec4[](vec4(0.0), vec4(0.0), vec4(0.0), vec4(0.0), vec4(0.0), vec4(0.0), vec4(0.0), vec4(0.0));
    // Planes before the chord get nothing, planes after it the whole particle: only the few planes
    // that cut the chord need an erf.
    float total = scale * (erfApprox(sk * chord.halfChord) - entry);
    int s = 0;
    do {  // not for: llvmpipe runs a for loop's body once more, masked (slices ≥ 4)
        float u = (uParams.y + float(s + 1) * spacing) / cosAxis - chord.tClosest;
        float value = u <= start ? 0.0 : u >= chord.halfChord ? total : scale * (erfApprox(sk * u) - entry);
        values[s / 4][s - 4 * (s / 4)] = value;
    } while (++s < slices);
    for (int a = 0; a < 8; ++a) outSlices[a] = values[a];
}
