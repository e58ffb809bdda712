#version 450 core
// The seam mask (media/blocks/block_seam.glsl): drawn over the rectangles of the blocks a mesh comes near
// (block_seam_mask_pass.cpp), one fragment per mask cell. A cell is set where, at one of its media
// texels, the opaque surface lies within the block's [front − reach, back + reach]: there
// block_composite.frag cuts the block, and the smooth shading's error shows along the cut.
#include "media/bindings.glsl"
#include "common/frame.glsl"
#include "media/blocks/block_data.glsl"
#include "media/blocks/block_seam.glsl"

layout(binding = MEDIA_SCENE_DEPTH_UNIT) uniform sampler2D uSceneDepth;
layout(binding = MEDIA_IMPOSTOR_DEPTHS_UNIT) uniform sampler2D uImpostorDepths;

layout(location = 1) uniform vec2 uFullResScale;  // full-resolution pixels per media texel
layout(location = 3) uniform ivec2 uMediaSize;    // the media target's texels
layout(location = 5) uniform int uCell;           // media texels per mask texel, per axis

flat in ivec2 vBlock;  // x: the block, y: its rank

layout(location = 0) out float outSeam;

void main() {
    BlockTile tile = blockTiles[vBlock.x];
    float reach = blockKernelReach(tile.centreRadius.w);
    ivec2 first = ivec2(gl_FragCoord.xy) * uCell;
    for (int k = 0; k < uCell * uCell; ++k) {
        ivec2 texel = first + ivec2(k % uCell, k / uCell);
        if (any(greaterThanEqual(texel, uMediaSize))) continue;
        // As block_composite.frag reads this texel's block and surface.
        vec2 fragCoord = (vec2(texel) + 0.5) * uFullResScale;
        vec2 ndc = fragCoord * frame.viewport.zw * 2.0 - 1.0;
        if (any(lessThan(ndc, tile.rect.xy)) || any(greaterThan(ndc, tile.rect.zw))) continue;
        ImpostorSample s = readImpostor(uImpostorDepths, uImpostorDepths, uImpostorDepths, uImpostorDepths, 0, tile, tileTexel(tile, ndc));
        if (!(s.tau > 0.0)) continue;
        vec3 origin, dir;
        cameraRay(fragCoord, origin, dir);
        float sceneDepth = linearViewDepth(texelFetch(uSceneDepth, ivec2(fragCoord), 0).r);
        float tSurface = rayDistanceAtViewDepth(dir, sceneDepth);
        float front = s.front + tile.instance.x, back = s.back + tile.instance.x;
        if (tSurface > front - reach && tSurface < back + reach) {
            outSeam = 1.0;
            return;
        }
    }
    discard;
}
