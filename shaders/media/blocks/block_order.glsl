// The compositing order's error where blocks overlap (block_partition.h overlappingBlockLists):
// blending dims a block's light by the whole of every block drawn after it and by none of those
// drawn before it. For the block's overlapping neighbours, read from their camera impostors at this
// pixel, the log of the factor that makes their attenuation of light scattered at ray distance t
// what their depth profiles put in front of t (lamp_neighbourhood.glsl does the same with single
// particles near a lamp). Drawn in the BLOCK_EXACT_SHADING build only: the factor needs many
// shading points per block (block_lighting.glsl exactShadingPieces), and with two the point's
// e^x misses the mean of e^x across a piece (Jensen's gap).
// Needs media/block_data and media/block_lighting.
#include "media/bindings.glsl"
layout(std430, binding = MEDIA_BLOCK_NEIGHBOURS_BINDING) readonly buffer BlockNeighbours { uvec2 blockNeighbours[]; };  // per block (first, count), then (block, rank)

const int MAX_ORDER_NEIGHBOURS = 32;  // block_partition.h kMaxOrderNeighbours

// The neighbours whose share in front changes across the block; the others add a constant.
int orderNeighbourCount = 0;
ProfileCdf orderProfile[MAX_ORDER_NEIGHBOURS];
float orderTau[MAX_ORDER_NEIGHBOURS];
float orderApplied[MAX_ORDER_NEIGHBOURS];  // the share of orderTau the blend applies to this block
float orderConstant = 0.0;                 // Σ τ·(applied − share in front) of the others
float orderEnd = 1e30;                     // the ray ends at the opaque surface

// The ray distance a camera tile's depth moments are taken about (block_data.glsl tileMomentOrigin).
float cameraMomentOrigin(BlockTile tile) {
    return frameOrthographic() ? dot(tile.centreRadius.xyz, frame.cameraForward.xyz) : length(tile.centreRadius.xyz);
}

// The share of a neighbour's optical depth that its own draw kept in front of the surface it is
// cut at: from its listed particles, as block_composite.frag's BLOCK_EXACT_CUT cuts a block a mesh
// comes near (blocksNearMeshes; the surface lies among this one's particles), else its profile's.
// The profile's share alone would make the factor apply a cut the draw did not make.
float drawnShareBefore(BlockTile tile, ProfileCdf cdf, vec3 origin, vec3 dir, float tSurface) {
    float listed = listedMassBefore(ivec2(tile.instance.zw), origin, dir, tSurface);
    return listed >= 0.0 ? listed : cdfMassBefore(cdf, tSurface);
}

// Reads block `block`'s neighbours at `ndc` (its rank in the draw order: `rank`; its shading points
// lie in `span`); returns their optical depth along the ray within `span`, where the factor varies
// (the exact build's piece count follows it; counting all of it costs time and gains no accuracy).
float gatherOrderNeighbours(int block, int rank, vec2 ndc, float tSurface, vec2 span, vec3 origin, vec3 dir, sampler2D depths,
                            sampler2D moments) {
    orderNeighbourCount = 0;
    orderConstant = 0.0;
    orderEnd = tSurface;
    float total = 0.0;
    uvec2 header = blockNeighbours[block];
    for (uint k = 0u; k < header.y && orderNeighbourCount < MAX_ORDER_NEIGHBOURS; ++k) {
        uvec2 entry = blockNeighbours[header.x + k];
        BlockTile tile = blockTiles[entry.x];
        if (!(tile.atlas.z > 0.0) || any(lessThan(ndc, tile.rect.xy)) || any(greaterThan(ndc, tile.rect.zw))) continue;
        ImpostorSample s = readImpostor(depths, moments, moments, moments, 1, tile, tileTexel(tile, ndc));
        if (!(s.tau > 0.0)) continue;
        s.front += tile.instance.x;
        s.back += tile.instance.x;
        float reach = blockKernelReach(tile.centreRadius.w);
        if (tSurface <= s.front - reach) continue;  // wholly behind the surface: not drawn, nothing in front
        BlockProfile profile = blockProfile(s.front, s.back, cameraMomentOrigin(tile), s.sums1.xy / s.tau);
        // The kernels' tails reach past [front, back]: cut there, the profile would put a neighbour's
        // mass behind a point it covers, and the factor would brighten the block.
        profile = widenedByTails(profile, vec2(reach));
        ProfileCdf cdf = profileCdf(profile);
        bool drawnAfter = int(entry.y) > rank;
        float applied = drawnAfter ? (tSurface < s.back + reach ? drawnShareBefore(tile, cdf, origin, dir, tSurface) : 1.0) : 0.0;
        float first = cdfMassBefore(cdf, min(span.x, tSurface)), last = cdfMassBefore(cdf, min(span.y, tSurface));
        total += s.tau * (last - first);
        if (first == last) {  // wholly in front of the shading points, or wholly behind them
            orderConstant += s.tau * (applied - first);
            continue;
        }
        orderApplied[orderNeighbourCount] = applied;
        orderProfile[orderNeighbourCount] = cdf;
        orderTau[orderNeighbourCount] = s.tau;
        ++orderNeighbourCount;
    }
    return total;
}

// Capped as lampOrderCorrection is (MAX_LAMP_LOG_FACTOR says why).
float blockOrderLogFactor(float t) {
    float sum = orderConstant;
    for (int k = 0; k < orderNeighbourCount; ++k) sum += orderTau[k] * (orderApplied[k] - cdfMassBefore(orderProfile[k], min(t, orderEnd)));
    return min(sum, MAX_LAMP_LOG_FACTOR);
}
