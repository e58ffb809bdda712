// Blocks of particles (media/block_partition.h) and their impostor tiles (media/impostor_atlas.h).
#include "media/bindings.glsl"
struct BlockTile {
    vec4 rect;          // the block's rectangle in the view's NDC: xy min, zw max
    vec4 atlas;         // its tile in the atlas: x, y, width, height in texels (width 0: not drawn)
    vec4 centreRadius;  // xyz origin-relative centre, w mean particle radius
    vec4 instance;      // x: ray-distance offset of the tile's depths (an instanced prototype), else 0;
                        // y: 1 when the tile has one texel per view pixel, on the pixel grid;
                        // z, w: the block's first item in impostorItems and its item count (0: none listed)
    vec4 lampSlices;    // x: 1 when the lamps' slices hold the block's particles one by one, not its light impostor
    vec4 reproject[3];  // an earlier frame's tile read through this view: rows x, y, w of NDC → texels; [0].w 1 when so
};

layout(std430, binding = MEDIA_IMPOSTOR_ITEMS_BINDING) readonly buffer ImpostorItems { uvec2 impostorItems[]; };  // (particle, block)
layout(std430, binding = MEDIA_BLOCK_TILES_BINDING) readonly buffer BlockTiles { BlockTile blockTiles[]; };

// The ray distance a tile's depth moments are taken about: its block centre's distance from the
// view's eye, or its view depth (orthographic). About the eye, E[t²] − E[t]² loses the variance to
// float rounding when a block lies far away compared with its particles' spread, and with it where a
// surface cuts their mass. An instance has its own centre, so the same moments put it where it is.
float tileMomentOrigin(BlockTile tile, mat4 view, bool perspective, vec3 eye) {
    return perspective ? length(tile.centreRadius.xyz - eye) : -(view * vec4(tile.centreRadius.xyz, 1.0)).z;
}

// How far a block's kernels reach past the [front, back] its impostor holds (each particle's
// ±√3·R/3, block_impostors.frag): R(1 − 1/√3), with 1.5× the block's mean radius for its largest
// members (as block_composite.frag cuts a block at a surface).
float blockKernelReach(float meanRadius) { return (1.0 - 0.57735027) * meanRadius * 1.5; }

// How far beyond a particle's silhouette, in tile texels, its impostor quad reaches: more than the
// √2 texels from a pixel centre to the farthest texel of its bilinear read. A tile on the pixel
// grid needs none: each pixel reads its own texel.
const float kEdgeBand = 1.5;

// Where a view NDC position falls in a tile, in atlas texels (through the view the tile was
// rendered for, when it is an earlier frame's: planning/block_reuse.h).
vec2 tileTexel(BlockTile tile, vec2 ndc) {
    if (tile.reproject[0].w > 0.5) {
        vec3 p = vec3(ndc, 1.0);
        return vec2(dot(tile.reproject[0].xyz, p), dot(tile.reproject[1].xyz, p)) / dot(tile.reproject[2].xyz, p);
    }
    vec2 local = (ndc - tile.rect.xy) / (tile.rect.zw - tile.rect.xy);
    return tile.atlas.xy + local * tile.atlas.zw;
}

// The view NDC position an atlas texel stands for.
vec2 tileNdc(BlockTile tile, vec2 texel) {
    vec2 local = (texel - tile.atlas.xy) / tile.atlas.zw;
    return tile.rect.xy + local * (tile.rect.zw - tile.rect.xy);
}

// The blocks' light (block_impostor_lighting.frag) is held at half the atlas's resolution: lit
// texel i of a tile covers its atlas texels 2i and 2i + 1 on each axis (tiles start at even texels,
// impostor_atlas.h kTileAlignment). A tile's place in that lit atlas, read bilinearly like any tile.
BlockTile litTile(BlockTile tile) {
    tile.atlas = vec4(tile.atlas.xy * 0.5, ceil(tile.atlas.zw * 0.5));
    tile.instance.y = 0.0;  // never on the pixel grid
    return tile;
}

// One impostor sample: total optical depth, front and back ray distances (Umenhoffer and Szirmay-Kalos §2.1), and the
// optical-depth-weighted sums of albedo, emission, g and the depth moments.
struct ImpostorSample {
    float tau;
    float front;
    float back;
    vec4 sums1;  // x free, yzw τ·albedo (light impostors: the depth moments)
    vec4 sums2;  // τ·emission, τ·g
    vec4 sums3;  // camera impostors: τ·mean, τ·(variance + mean²) of the depth along the ray
};

// The four texels and weights of a bilinear read at `texel`, kept inside the tile. A tile on the
// pixel grid is read at the pixel's own texel alone (float error in `texel` must not bring in a
// neighbour, whose edge distance could flip the silhouette test).
void tileBilinear(BlockTile tile, vec2 texel, out ivec2 q[4], out float w[4]) {
    vec2 p = clamp(texel, tile.atlas.xy + 0.5, tile.atlas.xy + tile.atlas.zw - 0.5) - 0.5;
    ivec2 maxTexel = ivec2(tile.atlas.xy + tile.atlas.zw) - 1;
    if (tile.instance.y > 0.5) {
        ivec2 own = min(ivec2(floor(p + 0.5)), maxTexel);
        for (int j = 0; j < 4; ++j) {
            q[j] = own;
            w[j] = j == 0 ? 1.0 : 0.0;
        }
        return;
    }
    ivec2 base = ivec2(floor(p));
    vec2 f = p - vec2(base);
    for (int j = 0; j < 4; ++j) {
        q[j] = min(base + ivec2(j & 1, j >> 1), maxTexel);
        w[j] = ((j & 1) == 1 ? f.x : 1.0 - f.x) * ((j >> 1) == 1 ? f.y : 1.0 - f.y);
    }
}

// Bilinear read of the depths and the first `layers` (0..3) additive layers inside one tile.
// Depths are averaged over the texels that hold particles only (an empty texel's depths are
// sentinels); optical depth and the sums are plain bilinear, cut to zero where the bilinear edge
// distance says the ray passes outside every particle (a texel wider than a pixel would otherwise
// spread optical depth up to a texel beyond the silhouette).
ImpostorSample readImpostor(sampler2D depths, sampler2D sums1, sampler2D sums2, sampler2D sums3, int layers, BlockTile tile,
                            vec2 texel) {
    ivec2 q[4];
    float w[4];
    tileBilinear(tile, texel, q, w);
    ImpostorSample s = ImpostorSample(0.0, 0.0, 0.0, vec4(0.0), vec4(0.0), vec4(0.0));
    float depthWeight = 0.0, edge = 0.0;
    for (int j = 0; j < 4; ++j) {
        if (w[j] == 0.0) continue;
        vec4 d = texelFetch(depths, q[j], 0);
        edge += w[j] * min(d.b, 1.0);  // unwritten: +3e38, which a weight of 1e-7 must not turn into 3e31
        s.tau += w[j] * d.a;
        if (d.a > 0.0) {
            s.front += w[j] * d.r;
            s.back -= w[j] * d.g;
            depthWeight += w[j];
        }
        if (layers > 0) s.sums1 += w[j] * texelFetch(sums1, q[j], 0);
        if (layers > 1) s.sums2 += w[j] * texelFetch(sums2, q[j], 0);
        if (layers > 2) s.sums3 += w[j] * texelFetch(sums3, q[j], 0);
    }
    if (!(edge <= 0.0)) return ImpostorSample(0.0, 0.0, 0.0, vec4(0.0), vec4(0.0), vec4(0.0));  // outside the silhouette
    if (depthWeight > 0.0) {
        s.front /= depthWeight;
        s.back /= depthWeight;
    }
    return s;
}
