#version 450 core
// Blocks mode (media/block_composite_pass.cpp): one quad per block over its screen rectangle,
// blocks back to front. The seam mask (block_seam_mask_pass.cpp) draws the same quads, widened.
#include "media/bindings.glsl"
#include "common/frame.glsl"
#include "common/fog.glsl"
#include "media/blocks/block_data.glsl"

layout(std430, binding = MEDIA_DRAW_ORDER_BINDING) readonly buffer DrawOrder { uint drawOrder[]; };

layout(location = 2) uniform int uFirstRank;  // the draw covers ranks uFirstRank onwards (block_composite_pass.cpp draws runs)
layout(location = 4) uniform vec2 uRectWidening;  // NDC added on every side of the rectangle (0 unless set)

flat out ivec2 vBlock;  // x: the block, y: its rank in the back-to-front order
flat out float vFog;    // the fog factor at the block's centre (common/fog.glsl)

void main() {
    int rank = uFirstRank + gl_InstanceID;
    vBlock = ivec2(drawOrder[rank], rank);
    BlockTile tile = blockTiles[vBlock.x];
    vFog = fogAtPoint(tile.centreRadius.xyz);
    if (tile.atlas.z <= 0.0) {
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
        return;
    }
    vec2 corner = vec2(gl_VertexID & 1, gl_VertexID >> 1);
    gl_Position = vec4(mix(tile.rect.xy - uRectWidening, tile.rect.zw + uRectWidening, corner), 0.5, 1.0);
}
