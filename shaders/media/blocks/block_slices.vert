#version 450 core
// Light slices from blocks (Umenhoffer and Szirmay-Kalos §2.2, media/block_slice_pass.cpp): one quad per block over its
// rectangle in the light view; the fragment shader spreads the block's light impostor over the slices.
#include "media/blocks/block_data.glsl"

flat out int vBlock;

void main() {
    vBlock = gl_InstanceID;
    BlockTile tile = blockTiles[vBlock];
    if (tile.atlas.z <= 0.0) {
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
        return;
    }
    vec2 corner = vec2(gl_VertexID & 1, gl_VertexID >> 1);
    gl_Position = vec4(mix(tile.rect.xy, tile.rect.zw, corner), 0.0, 1.0);
}
