#version 450 core
// One particle's contribution to one pixel: exact optical depth τ of the kernel along the pixel's
// ray (clipped at the opaque surface when soft particles are on), opacity α = 1 − e^−τ, and the
// in-scattered source J at the kernel's centroid on that segment. Output (α·J, α) blends
// premultiplied over what is behind; the alpha channel accumulates the view transmittance.
// PARTICLE_SPLAT_RUN: drawn by the splat pass for the particles a mesh lies inside, into a target
// whose first pixel may be offset (the edges' rect), under its depth or stencil test.
#include "media/bindings.glsl"
#include "common/math.glsl"
#include "common/frame.glsl"
#include "common/lights.glsl"
#include "common/light_views.glsl"
#include "media/common/slices.glsl"
#include "media/common/optics.glsl"
#include "media/common/particle_data.glsl"
#include "media/common/lighting.glsl"

layout(binding = MEDIA_SCENE_DEPTH_UNIT) uniform sampler2D uSceneDepth;
layout(location = 0) uniform int uSoftParticles;
layout(location = 1) uniform vec2 uFullResScale;  // full-resolution pixels per target texel (offscreen media)
#ifdef PARTICLE_SPLAT_RUN
layout(location = 13) uniform vec2 uFragOffset;  // the target's first pixel in the viewport
// The tests first: the stencil of the edges' redraw then spares the shading (no depth is written).
layout(early_fragment_tests) in;
#endif

flat in ivec2 vParticle;  // x: index, y: draw rank
flat in float vFog;        // the fog factor at the particle's centre (common/fog.glsl)

layout(location = 0) out vec4 outColor;

void main() {
    GpuParticle particle = particles[vParticle.x];
    vec3 origin, dir;
    vec2 fragCoord = gl_FragCoord.xy * uFullResScale;  // the full-resolution position this texel stands for
#ifdef PARTICLE_SPLAT_RUN
    fragCoord += uFragOffset;
#endif
    cameraRay(fragCoord, origin, dir);
    Chord chord = chordOf(origin, dir, particle.positionRadius.xyz, particle.positionRadius.w);
    if (chord.halfChord <= 0.0) discard;

    float sceneDepth = linearViewDepth(texelFetch(uSceneDepth, ivec2(fragCoord), 0).r);
    float tSurface = rayDistanceAtViewDepth(dir, sceneDepth);
    float tEnd = 1e30;
    if (uSoftParticles != 0) {
        tEnd = tSurface;  // the exact soft-particle fade: only the part of the kernel in front counts
    } else if (chord.tClosest > tSurface) {
        discard;          // classic billboard: the whole particle is hidden once its plane is behind
    }
    float radius = particle.positionRadius.w;
    float u0 = max(0.0, chord.tClosest - chord.halfChord) - chord.tClosest;  // the medium starts at the eye
    float u1 = min(tEnd - chord.tClosest, chord.halfChord);
    if (u1 <= u0) discard;
    float tau = particle.albedoSigma.w * chordIntegral(chord, radius, u0, u1);
    float alpha = oneMinusExpNeg(tau);
    if (alpha <= 0.0) discard;
    float lo = max(u0, -chord.halfChord), hi = min(u1, chord.halfChord);
    LayerOrder layer = LayerOrder(vParticle.x, vParticle.y, tEnd, uSoftParticles != 0 ? 1e30 : tSurface);
    vec3 source = segmentSource(origin, dir, chord, radius, lo, hi, chordShadingPoint(chord, radius, u0, u1, tau), tau, particle, layer);
    source = mix(frame.fogColor.rgb, source, vFog);
    outColor = vec4(source * alpha, alpha);
}
