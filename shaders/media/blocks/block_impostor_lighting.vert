#version 450 core
// Blocks mode (blocks/block_impostor_lighting_pass.cpp): one quad per block over its tile of the
// lit atlas (block_data.glsl litTile), in the composite's back-to-front ranks (the lamps' ordering
// reads them).
#include "media/bindings.glsl"
#include "media/blocks/block_data.glsl"

layout(std430, binding = MEDIA_DRAW_ORDER_BINDING) readonly buffer DrawOrder { uint drawOrder[]; };

layout(location = 0) uniform vec2 uLitSize;   // the lit atlas, texels
layout(location = 2) uniform int uFirstRank;  // the draw covers ranks uFirstRank onwards

flat out ivec2 vBlock;  // x: the block, y: its rank in the back-to-front order

void main() {
    int rank = uFirstRank + gl_InstanceID;
    vBlock = ivec2(drawOrder[rank], rank);
    BlockTile tile = blockTiles[vBlock.x];
    if (tile.atlas.z <= 0.0) {
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
        return;
    }
    vec4 lit = litTile(tile).atlas;
    vec2 corner = vec2(gl_VertexID & 1, gl_VertexID >> 1);
    gl_Position = vec4((lit.xy + corner * lit.zw) / uLitSize * 2.0 - 1.0, 0.5, 1.0);
}
