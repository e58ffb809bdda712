#version 450 core
// The exact tier's slab (media/sheets/sheet_pass.cpp): one particle's part of the pixel's ray
// between the sheet's planes, clipped at the eye and at the opaque surface; its optical depth τ in
// closed form and its source J shaded as particles.frag shades a pixel, over the slab alone
// (common/lighting.glsl segmentSource). Output (τ·J, τ) is added into the sheet.
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
layout(location = 1) uniform vec2 uFullResScale;  // full-resolution pixels per target texel (offscreen media)
layout(location = 2) uniform vec2 uSheet;         // the sheet's near and far view depth (m)

flat in ivec2 vParticle;  // x: index, y: rank in the view-depth order
flat in float vFog;       // the fog factor at the particle's centre (common/fog.glsl)

layout(location = 0) out vec4 outColor;

void main() {
    GpuParticle particle = particles[vParticle.x];
    vec3 origin, dir;
    vec2 fragCoord = gl_FragCoord.xy * uFullResScale;
    cameraRay(fragCoord, origin, dir);
    Chord chord = chordOf(origin, dir, particle.positionRadius.xyz, particle.positionRadius.w);
    if (chord.halfChord <= 0.0) discard;
    // Along the ray, a plane of view depth z lies at t = z / cos θ (orthographic: t = z).
    float perDepth = frameOrthographic() ? 1.0 : 1.0 / max(dot(dir, frame.cameraForward.xyz), 1e-6);
    float tSurface = linearViewDepth(texelFetch(uSceneDepth, ivec2(fragCoord), 0).r) * perDepth;
    float radius = particle.positionRadius.w;
    float u0 = max(max(0.0, uSheet.x * perDepth), chord.tClosest - chord.halfChord) - chord.tClosest;
    float u1 = min(min(uSheet.y * perDepth, tSurface) - chord.tClosest, chord.halfChord);
    if (u1 <= u0) discard;
    float tau = particle.albedoSigma.w * chordIntegral(chord, radius, u0, u1);
    if (!(tau > 0.0)) discard;
    LayerOrder layer = LayerOrder(vParticle.x, vParticle.y, tSurface, 1e30);
    vec3 source = segmentSource(origin, dir, chord, radius, u0, u1, chordShadingPoint(chord, radius, u0, u1, tau), tau, particle, layer);
    source = mix(frame.fogColor.rgb, source, vFog);
    outColor = vec4(source * tau, tau);
}
