#version 450 core
// A block impostor texel acts as one "super-particle" (Umenhoffer and Szirmay-Kalos §2): opacity from its
// optical depth, in-scattering at its optical-depth-weighted shading point with its weighted albedo, emission
// and g. Where the opaque surface lies inside the block's [front, back] interval, the optical depth is
// scaled by the share of its mass in front of it (Umenhoffer and Szirmay-Kalos §2.4, with the block's depth profile
// instead of uniform density), so a mesh crossing a cloud shows no billboard plane.
#include "media/bindings.glsl"
#include "common/math.glsl"
#include "common/frame.glsl"
#include "common/lights.glsl"
#include "common/light_views.glsl"
#include "media/common/slices.glsl"
#include "media/common/optics.glsl"
#include "media/common/particle_data.glsl"
#include "media/common/lighting.glsl"
#include "media/blocks/block_data.glsl"
#include "media/blocks/block_lighting.glsl"
#include "media/blocks/block_order.glsl"
#include "media/blocks/block_seam.glsl"

layout(binding = MEDIA_SCENE_DEPTH_UNIT) uniform sampler2D uSceneDepth;
layout(binding = MEDIA_IMPOSTOR_DEPTHS_UNIT) uniform sampler2D uImpostorDepths;
layout(binding = MEDIA_IMPOSTOR_SUMS1_UNIT) uniform sampler2D uImpostorSums1;
layout(binding = MEDIA_IMPOSTOR_SUMS2_UNIT) uniform sampler2D uImpostorSums2;
layout(binding = MEDIA_IMPOSTOR_MOMENTS_UNIT) uniform sampler2D uImpostorMoments;  // τ·mean, τ·(variance + mean²) of the depth along the ray
layout(binding = MEDIA_SEAM_MASK_UNIT) uniform sampler2D uSeamMask;         // media/blocks/block_seam.glsl; read where uSeamPart is 2

layout(location = 1) uniform vec2 uFullResScale;  // full-resolution pixels per target texel (offscreen media)
// Which texels this draw shades (block_composite_pass.cpp draws the blocks of a seam twice, once
// per part, each behind a stencil test): 0 all; 1 only those off the seam (seamWeight 0); 2 only
// those near it, where the BLOCK_EXACT_SHADING build shades exactly, mixed with the smooth shading
// as seamWeight says.
layout(location = 3) uniform int uSeamPart;
layout(location = 5) uniform int uSeamCell;  // media texels per seam mask texel, per axis

flat in ivec2 vBlock;  // x: the block, y: its rank in the back-to-front order
flat in float vFog;     // the fog factor at the block's centre (common/fog.glsl)

// The seam stencil is only read (block_composite_pass.cpp), so testing it before shading changes
// nothing but the cost: a texel of the other part is never shaded.
layout(early_fragment_tests) in;

layout(location = 0) out vec4 outColor;

void main() {
    BlockTile tile = blockTiles[vBlock.x];
    vec2 fragCoord = gl_FragCoord.xy * uFullResScale;  // the full-resolution position this texel stands for
    vec2 ndc = fragCoord * frame.viewport.zw * 2.0 - 1.0;
    float seam = uSeamPart == 2 ? seamWeight(uSeamMask, gl_FragCoord.xy, uSeamCell) : (uSeamPart == 1 ? 0.0 : 1.0);
    ImpostorSample s = readImpostor(uImpostorDepths, uImpostorSums1, uImpostorSums2, uImpostorMoments, 3, tile, tileTexel(tile, ndc));
    if (!(s.tau > 0.0)) discard;
    // An instance of the prototype sits farther or nearer than the prototype the tile was made for.
    s.front += tile.instance.x;
    s.back += tile.instance.x;

    vec3 origin, dir;
    cameraRay(fragCoord, origin, dir);
    float sceneDepth = linearViewDepth(texelFetch(uSceneDepth, ivec2(fragCoord), 0).r);
    float tSurface = frameOrthographic() ? sceneDepth : sceneDepth / max(dot(dir, frame.cameraForward.xyz), 1e-6);
    // [front, back] holds each particle's ±√3·R/3 (block_impostors.frag); its kernel reaches R.
    // The tile knows only the block's mean radius: 1.5× it covers members up to that size, and a
    // larger member's far tail takes the profile's cut.
    float reach = blockKernelReach(tile.centreRadius.w);
    if (tSurface <= s.front - reach) discard;  // the block lies wholly behind the surface
    // The share of the block's optical depth in front of the surface: exact from the block's own
    // particles where the surface lies among them, else from the depth profile the impostor's
    // moments give (block_lighting.glsl blockProfile), which also shapes the shading below.
    float momentOrigin = frameOrthographic() ? dot(tile.centreRadius.xyz, frame.cameraForward.xyz) : length(tile.centreRadius.xyz);
    BlockProfile profile = blockProfile(s.front, s.back, momentOrigin, s.sums3.xy / s.tau);
    bool cut = tSurface < s.back + reach;
    // The exact cut walks the block's particles; the build without it (block_composite_pass.cpp
    // draws with it only the blocks a mesh comes near) keeps the profile's cut for safety.
#ifdef BLOCK_EXACT_CUT
    ivec2 items = ivec2(tile.instance.zw);  // (count 0: an instance, whose particles are not listed)
    float share = cut ? listedMassBefore(items, origin, dir, tSurface) : 1.0;
    if (share < 0.0) share = profileMassBefore(profile, tSurface);
#else
    float share = cut ? profileMassBefore(profile, tSurface) : 1.0;
#endif
    float tau = s.tau * share;
    float alpha = oneMinusExpNeg(tau);
    if (alpha <= 0.0) discard;

    float end = min(s.back, tSurface);
    GpuParticle block;
    block.positionRadius = vec4(tile.centreRadius.xyz, tile.centreRadius.w);
    block.albedoSigma = vec4(s.sums1.yzw / s.tau, 0.0);
    block.emissionG = vec4(s.sums2.xyz / s.tau, clamp(s.sums2.w / s.tau, -0.999, 0.999));
    block.extra = vec4(0.0, tile.lampSlices.x, 0.0, 0.0);  // y: blockLightDepth's (block_own_optical_depth.glsl)
    LayerOrder layer = LayerOrder(-1, vBlock.y, tSurface, 1e30);
    // What the light sees of it ends at the surface; a surface just in front of the block cuts
    // only its kernels' tails, which lie within `reach` of it.
    profile.front = end > s.front ? s.front : end - reach;
    profile.back = end;
    vec2 tails = vec2(end > s.front ? reach : 0.0, end < s.back ? 0.0 : reach);  // none past a cut
    // What is left in front of a cut is no longer the normal the moments describe: its own
    // particles say where its mass lies.
#ifdef BLOCK_EXACT_CUT
    if (cut && share > 0.0) {
        profile.origin = origin;
        profile.dir = dir;
        profile.listed = items;
    }
#endif
    vec3 source = vec3(0.0);
#ifdef BLOCK_EXACT_SHADING
    BlockProfile shaded = widenedByTails(profile, tails);  // where blockSegmentSource's shading points lie
    vec2 span = vec2(shaded.front, shaded.back);
    float neighbours = gatherOrderNeighbours(vBlock.x, vBlock.y, ndc, tSurface, span, origin, dir, uImpostorDepths, uImpostorMoments);
    // The exact shading, and where the seam's weight falls off, the smooth one too (a loop, not two
    // calls: one copy of blockSegmentSource's code).
    for (int part = 0; part < (seam < 1.0 ? 2 : 1); ++part) {
        bool exact = part == 0;
        int pieces = exact ? exactShadingPieces(tau, neighbours) : BLOCK_SHADING_PIECES;
        source += (exact ? seam : 1.0 - seam) *
                  blockSegmentSource(origin, dir, profile, tails, tau, block, ivec2(tile.instance.zw), layer, pieces, exact);
    }
#else
    source = blockSegmentSource(origin, dir, profile, tails, tau, block, ivec2(tile.instance.zw), layer, BLOCK_SHADING_PIECES, false);
#endif
    source = mix(frame.fogColor.rgb, source, vFog);
    outColor = vec4(source * alpha, alpha);
}
