#version 450 core
// The light of a block no mesh comes near, once per two by two texels of its camera impostor
// (block_data.glsl litTile) instead of once per pixel: shadeBlock along the ray through their
// shared corner, with no surface on it. block_composite.frag's BLOCK_LIT_IMPOSTOR build reads it
// back bilinearly, premultiplied (rgb: radiance × opacity, a: opacity), and adds the fog and the
// pixel's own opacity.
// Once per particle or impostor texel: reading the slice crops costs little here (light_transmittance.glsl).
#define MEDIA_SLICE_CROPS
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
#include "media/blocks/block_shade.glsl"

layout(binding = MEDIA_IMPOSTOR_DEPTHS_UNIT) uniform sampler2D uImpostorDepths;
layout(binding = MEDIA_IMPOSTOR_SUMS1_UNIT) uniform sampler2D uImpostorSums1;
layout(binding = MEDIA_IMPOSTOR_SUMS2_UNIT) uniform sampler2D uImpostorSums2;
layout(binding = MEDIA_IMPOSTOR_MOMENTS_UNIT) uniform sampler2D uImpostorMoments;

flat in ivec2 vBlock;  // x: the block, y: its rank in the back-to-front order

layout(location = 0) out vec4 outLit;

// The mean of the four impostor texels a lit texel covers (readImpostor's, without its silhouette
// cut): a pixel the composite draws lies at or beside one of them, so its lit texel is never empty.
ImpostorSample readFour(BlockTile tile, vec2 corner) {
    ImpostorSample s = ImpostorSample(0.0, 0.0, 0.0, vec4(0.0), vec4(0.0), vec4(0.0));
    ivec2 lo = ivec2(tile.atlas.xy), hi = ivec2(tile.atlas.xy + tile.atlas.zw) - 1;
    float held = 0.0;
    for (int j = 0; j < 4; ++j) {
        ivec2 q = clamp(ivec2(corner) - 1 + ivec2(j & 1, j >> 1), lo, hi);
        vec4 d = texelFetch(uImpostorDepths, q, 0);
        s.tau += 0.25 * d.a;
        s.sums1 += 0.25 * texelFetch(uImpostorSums1, q, 0);
        s.sums2 += 0.25 * texelFetch(uImpostorSums2, q, 0);
        s.sums3 += 0.25 * texelFetch(uImpostorMoments, q, 0);
        if (d.a > 0.0) {
            s.front += d.r;
            s.back -= d.g;
            held += 1.0;
        }
    }
    s.front /= max(held, 1.0);
    s.back /= max(held, 1.0);
    return s;
}

void main() {
    BlockTile tile = blockTiles[vBlock.x];
    vec2 corner = 2.0 * gl_FragCoord.xy;  // the atlas position between the four texels it covers
    vec2 ndc = tileNdc(tile, corner);
    ImpostorSample s = readFour(tile, corner);
    outLit = vec4(0.0);
    if (!(s.tau > 0.0)) return;
    s.front += tile.instance.x;
    s.back += tile.instance.x;
    vec3 origin, dir;
    cameraRay((ndc * 0.5 + 0.5) / frame.viewport.zw, origin, dir);
    BlockShade shade = shadeBlock(tile, vBlock, s, origin, dir, 1e30, ndc, 1.0);
    outLit = vec4(shade.source * shade.alpha, shade.alpha);
}
