#version 450 core
// Depth impostors (Umenhoffer and Szirmay-Kalos §2.1, media/block_impostor_pass.cpp): every particle is drawn into its
// block's tile of the atlas, where the tile stands for the block's rectangle in the view (the
// camera or a light view). Clip distances keep each quad inside its tile.
#include "common/math.glsl"
#include "media/common/particle_data.glsl"
#include "media/blocks/block_data.glsl"

layout(location = 0) uniform mat4 uView;
layout(location = 1) uniform mat4 uProjection;
layout(location = 2) uniform vec4 uParams;     // x: perspective, y: near depth
layout(location = 3) uniform vec2 uAtlasSize;

flat out int vParticle;
flat out int vBlock;
out float gl_ClipDistance[4];

const vec2 kCorners[4] = vec2[](vec2(-1.0, -1.0), vec2(1.0, -1.0), vec2(-1.0, 1.0), vec2(1.0, 1.0));

void main() {
    uvec2 item = impostorItems[gl_InstanceID];
    vParticle = int(item.x);
    vBlock = int(item.y);
    BlockTile tile = blockTiles[item.y];
    vec2 corner = kCorners[gl_VertexID];
    if (tile.atlas.z <= 0.0) {
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
        for (int i = 0; i < 4; ++i) gl_ClipDistance[i] = -1.0;
        return;
    }
    vec4 pr = particles[item.x].positionRadius;
    vec3 c = (uView * vec4(pr.xyz, 1.0)).xyz;
    vec2 ndc;
    if (uParams.x < 0.5) {
        vec4 clip = uProjection * vec4(c + vec3(corner * pr.w, 0.0), 1.0);
        ndc = clip.xy / clip.w;
    } else {
        // The tangent cone's quad, perpendicular to the eye→centre axis. Its corners reach further
        // sideways than the sphere; the ndc division below is only valid for corners in front of the
        // near plane, so a sphere close to the eye and seen obliquely (a lamp beside a particle) takes
        // the whole tile too: a corner behind the eye would flip the quad off the tile and drop the
        // particle from that light view.
        float d = length(c);
        bool whole = d <= pr.w * 1.001 || -c.z - pr.w <= uParams.y * 2.0;
        vec3 right = vec3(1.0, 0.0, 0.0), up = vec3(0.0, 1.0, 0.0);
        float half_ = 0.0;
        if (!whole) {
            vec3 axis = c / d;
            vec3 helper = abs(axis.y) < 0.9 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
            right = normalize(cross(axis, helper));
            up = cross(right, axis);
            half_ = pr.w * d / sqrt(d * d - pr.w * pr.w);
            float nearestCorner = -c.z - (abs(right.z) + abs(up.z)) * half_;  // the corner closest to the eye's plane
            whole = nearestCorner <= uParams.y * 2.0;
        }
        if (whole) {
            ndc = mix(tile.rect.xy, tile.rect.zw, corner * 0.5 + 0.5);
        } else {
            vec4 clip = uProjection * vec4(c + (right * corner.x + up * corner.y) * half_, 1.0);
            ndc = clip.xy / clip.w;
        }
    }
    // kEdgeBand texels more on every side: texels just outside the particle get its edge distance
    // (block_impostors.frag), so every texel of a covered pixel's bilinear read has one.
    if (tile.instance.y < 0.5) ndc += corner * kEdgeBand * (tile.rect.zw - tile.rect.xy) / tile.atlas.zw;
    vec2 texel = tileTexel(tile, ndc);
    vec2 local = (texel - tile.atlas.xy) / tile.atlas.zw;
    gl_ClipDistance[0] = local.x;
    gl_ClipDistance[1] = 1.0 - local.x;
    gl_ClipDistance[2] = local.y;
    gl_ClipDistance[3] = 1.0 - local.y;
    gl_Position = vec4(texel / uAtlasSize * 2.0 - 1.0, 0.0, 1.0);
}
