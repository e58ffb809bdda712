#version 450 core
// One particle's share of a block impostor texel, along the exact view ray the texel stands for.
// Target 0 blends MIN on rgb and ADD on alpha (Umenhoffer and Szirmay-Kalos §2.1, one pass): r = front (ray distance
// where the first particle starts), g = −back, b = edge distance, a = optical depth. Targets 1 and 2 add the
// optical-depth-weighted albedo, emission and g (camera impostors only), target 3 the depth moments.
#include "common/math.glsl"
#include "media/common/optics.glsl"
#include "media/common/particle_data.glsl"
#include "media/blocks/block_data.glsl"
#include "media/common/view_rays.glsl"

layout(location = 0) uniform mat4 uView;
layout(location = 2) uniform vec4 uParams;  // x: perspective
layout(location = 4) uniform vec2 uHalfExtent;  // tan of the half angles, or half size in metres (view_rays.glsl)
layout(location = 5) uniform vec3 uEye;

flat in int vParticle;
flat in int vBlock;

layout(location = 0) out vec4 outDepths;
layout(location = 1) out vec4 outSums1;
layout(location = 2) out vec4 outSums2;
layout(location = 3) out vec4 outMoments;  // τ·mean, τ·(variance + mean²) of the depth along the ray, about tileMomentOrigin

void main() {
    GpuParticle particle = particles[vParticle];
    BlockTile tile = blockTiles[vBlock];
    vec3 origin, dir;
    viewRay(tileNdc(tile, gl_FragCoord.xy), uHalfExtent, uView, uParams.x > 0.5, uEye, origin, dir);
    float radius = particle.positionRadius.w;
    Chord chord = chordOf(origin, dir, particle.positionRadius.xyz, radius);
    // Blue (MIN) holds the edge distance: how far the ray passes outside the particle's sphere,
    // negative inside, as an angle for a perspective view so particles at different distances
    // compare. Its bilinear read crosses zero at the silhouette, where optical depth jumps to zero.
    float edge = (sqrt(chord.b2) - radius) / (uParams.x > 0.5 ? max(abs(chord.tClosest), radius) : 1.0);
    float lo = max(-chord.halfChord, -chord.tClosest);  // rays start at the eye (or the view plane)
    if (chord.halfChord > 0.0 && lo >= chord.halfChord) discard;  // the chord is behind the eye
    if (chord.halfChord <= 0.0) {
        outDepths = vec4(3.0e38, 3.0e38, edge, 0.0);
        outSums1 = outSums2 = outMoments = vec4(0.0);
        return;
    }
    float tau = particle.albedoSigma.w * chordIntegral(chord, radius, lo, chord.halfChord);
    if (!(tau > 0.0)) discard;
    // Front and back of the particle's mass, not of its truncation sphere: a uniform density
    // between them (Umenhoffer and Szirmay-Kalos §2.4) matches a Gaussian of deviation s = R/3 best (same mean and
    // variance) over ±√3·s, so that is the extent each particle contributes to the interval a
    // block's depth profile is cut to.
    float extent = min(chord.halfChord, 1.7320508 * radius / 3.0);
    float front = chord.tClosest + max(lo, -extent);
    float back = chord.tClosest + max(extent, lo);
    outDepths = vec4(front, -back, edge, tau);
    outSums1 = tau * vec4(0.0, particle.albedoSigma.rgb);  // x: free
    outSums2 = tau * vec4(particle.emissionG.rgb, particle.emissionG.w);
    vec2 moments = chordMoments(chord, radius, lo, chord.halfChord);
    float mean = chord.tClosest + moments.x - tileMomentOrigin(tile, uView, uParams.x > 0.5, uEye);
    outMoments = tau * vec4(mean, moments.y + mean * mean, 0.0, 0.0);
}
