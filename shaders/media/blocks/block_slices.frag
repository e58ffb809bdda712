#version 450 core
// A block's optical depth towards the light, spread over the slice planes (Umenhoffer and Szirmay-Kalos §2.2): plane k
// gets τ · Φ((t_k − μ)/σ), a normal with the block's optical-depth-weighted mean and deviation along
// the light ray, cut where the block's kernels start (and at a lamp) and complete past where they
// end (block_light_profile.glsl). Additive, like the particle slices.
#include "media/bindings.glsl"
#include "common/math.glsl"
#include "media/common/optics.glsl"
#include "media/blocks/block_data.glsl"
#include "media/blocks/block_light_profile.glsl"
#include "media/common/view_rays.glsl"

layout(location = 0) uniform mat4 uView;
layout(location = 2) uniform vec4 uParams;  // x: perspective, y: slice near, z: slice far, w: slices
layout(location = 3) uniform vec2 uHalfExtent;  // tan of the half angles, or half size in metres (view_rays.glsl)
layout(location = 4) uniform vec2 uViewportSize;
layout(location = 6) uniform vec3 uLightOrigin;
layout(binding = MEDIA_IMPOSTOR_DEPTHS_UNIT) uniform sampler2D uImpostorDepths;
layout(binding = MEDIA_SLICE_IMPOSTOR_MOMENTS_UNIT) uniform sampler2D uImpostorMoments;

flat in int vBlock;

layout(location = 0) out vec4 outSlices[8];

void main() {
    BlockTile tile = blockTiles[vBlock];
    vec2 ndc = gl_FragCoord.xy / uViewportSize * 2.0 - 1.0;
    ImpostorSample s = readImpostor(uImpostorDepths, uImpostorMoments, uImpostorMoments, uImpostorMoments, 1, tile, tileTexel(tile, ndc));
    if (!(s.tau > 0.0)) discard;
    vec3 origin, dir;
    viewRay(ndc, uHalfExtent, uView, uParams.x > 0.5, uLightOrigin, origin, dir);
    vec3 axis = -vec3(uView[0][2], uView[1][2], uView[2][2]);
    float cosAxis = uParams.x > 0.5 ? max(dot(dir, axis), 1e-6) : 1.0;
    // How the block's optical depth is spread along the light ray: a Gaussian with the mean and
    // variance of its particles' kernels (moments the impostor accumulates), which follows a dense
    // core far better than uniform density between the outermost spheres.
    float mean = s.sums1.x / s.tau;  // about tileMomentOrigin, which puts an instance where it is
    float deviation = sqrt(max(s.sums1.y / s.tau - mean * mean, 0.0));
    mean += tileMomentOrigin(tile, uView, uParams.x > 0.5, uLightOrigin);
    BlockLightProfile profile = blockLightProfile(mean, deviation, s.front, s.back, blockKernelReach(tile.centreRadius.w), uParams.x > 0.5);
    int slices = int(uParams.w);
    float spacing = (uParams.z - uParams.y) / uParams.w;
    vec4 values[8] = vec4[](vec4(0.0), vec4(0.0), vec4(0.0), vec4(0.0), vec4(0.0), vec4(0.0), vec4(0.0), vec4(0.0));
    for (int k = 0; k < slices; ++k) {
        float t = (uParams.y + float(k + 1) * spacing) / cosAxis;
        values[k / 4][k - 4 * (k / 4)] = s.tau * blockLightShare(profile, t);
    }
    for (int a = 0; a < 8; ++a) outSlices[a] = values[a];
}
