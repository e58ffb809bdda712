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
layout(location = 6) uniform vec2 uFragOffset;    // the full-resolution pixel of the target's first texel (the edges: their rect)
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

// After the impostor samplers, which the BLOCK_EXACT_SHADING build of shadeBlock reads.
#include "media/blocks/block_shade.glsl"

// BLOCK_LIT_IMPOSTOR: the block's light was shaded once per two by two impostor texels
// (block_impostor_lighting.frag) with no surface on the ray, and is read here bilinearly,
// premultiplied, while the opacity stays the pixel's own. A block no mesh comes near
// (blocksNearMeshes) is never cut; one that a mesh comes near takes it only off the seam.
#ifdef BLOCK_LIT_IMPOSTOR
layout(binding = MEDIA_IMPOSTOR_LIT_UNIT) uniform sampler2D uImpostorLit;

vec3 litSource(BlockTile tile, vec2 texel) {
    ivec2 q[4];
    float w[4];
    tileBilinear(litTile(tile), 0.5 * texel, q, w);
    vec4 lit = vec4(0.0);
    for (int j = 0; j < 4; ++j) lit += w[j] * texelFetch(uImpostorLit, q[j], 0);
    return lit.a > 0.0 ? lit.rgb / lit.a : vec3(0.0);
}
#endif

void main() {
    BlockTile tile = blockTiles[vBlock.x];
    vec2 fragCoord = gl_FragCoord.xy * uFullResScale + uFragOffset;  // the full-resolution position this texel stands for
    vec2 ndc = fragCoord * frame.viewport.zw * 2.0 - 1.0;
    vec2 texel = tileTexel(tile, ndc);
#if defined(BLOCK_LIT_IMPOSTOR) && !defined(BLOCK_EXACT_CUT)
    ImpostorSample s = readImpostor(uImpostorDepths, uImpostorSums1, uImpostorSums2, uImpostorMoments, 0, tile, texel);
#else
    ImpostorSample s = readImpostor(uImpostorDepths, uImpostorSums1, uImpostorSums2, uImpostorMoments, 3, tile, texel);
#endif
    if (!(s.tau > 0.0)) discard;
    // An instance of the prototype sits farther or nearer than the prototype the tile was made for.
    s.front += tile.instance.x;
    s.back += tile.instance.x;

    vec3 origin, dir;
    cameraRay(fragCoord, origin, dir);
    float sceneDepth = linearViewDepth(texelFetch(uSceneDepth, ivec2(fragCoord), 0).r);
    float tSurface = rayDistanceAtViewDepth(dir, sceneDepth);
#if defined(BLOCK_LIT_IMPOSTOR) && defined(BLOCK_EXACT_CUT)
    // Off the seam (block_shading=seam draws the exact shading there): the surface cuts the block's
    // opacity, and at most its kernels' tails, whose light the texels' stands for.
    BlockProfile profile;
    bool cut;
    float share = blockShareBefore(tile, s, origin, dir, tSurface, profile, cut);
    BlockShade shade = BlockShade(litSource(tile, texel), oneMinusExpNeg(s.tau * share));
#elif defined(BLOCK_LIT_IMPOSTOR)
    if (tSurface <= s.front - blockKernelReach(tile.centreRadius.w)) discard;  // wholly behind the surface
    BlockShade shade = BlockShade(litSource(tile, texel), oneMinusExpNeg(s.tau));
#else
    float seam = uSeamPart == 2 ? seamWeight(uSeamMask, gl_FragCoord.xy, uSeamCell) : (uSeamPart == 1 ? 0.0 : 1.0);
    BlockShade shade = shadeBlock(tile, vBlock, s, origin, dir, tSurface, ndc, seam);
#endif
    if (shade.alpha <= 0.0) discard;
    outColor = vec4(mix(frame.fogColor.rgb, shade.source, vFog) * shade.alpha, shade.alpha);
}
