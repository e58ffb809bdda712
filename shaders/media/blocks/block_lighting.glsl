// Light scattered by a block's visible segment of a view ray (blocks mode's counterpart of
// lighting.glsl segmentSource): the same lights, with a block's depth profile (BlockProfile) in
// place of a particle's kernel. Needs media/lighting and media/block_data.
#include "media/blocks/block_light_profile.glsl"
#include "media/blocks/block_own_optical_depth.glsl"

// block_order.glsl (the BLOCK_EXACT_SHADING build): the log of the factor that makes the overlapping
// blocks' attenuation of light scattered at ray distance t exact; 0 in the other builds.
float blockOrderLogFactor(float t);

// How a block's optical depth lies along one ray: a Gaussian with the impostor's mean and deviation
// of depth, cut to the block's [front, back] (Umenhoffer and Szirmay-Kalos §2.4 assumes uniform density over that
// interval; the moments follow where the mass actually lies, as the light slices spread a block in
// block_slices.frag). A profile without spread (one particle's centre on the ray's plane) is
// uniform over [front, back].
struct BlockProfile {
    float front;
    float back;
    float mean;
    float deviation;  // 0: uniform
    vec3 origin;      // the ray, for `listed`
    vec3 dir;
    ivec2 listed;     // the block's first item in impostorItems and its count; count 0: use the normal
};

// `moments`: the mean and second moment of ray distance − `origin` (block_data.glsl tileMomentOrigin).
BlockProfile blockProfile(float front, float back, float origin, vec2 moments) {
    float deviation = sqrt(max(moments.y - moments.x * moments.x, 0.0));
    return BlockProfile(front, back, origin + moments.x, deviation > 1e-6 * max(abs(back), 1.0) ? deviation : 0.0, vec3(0.0),
                        vec3(0.0, 0.0, 1.0), ivec2(0));
}

// The optical depth of the listed particles `items` along the ray from the eye to ray distance t
// (the ray starts at the eye, as in the impostor).
float listedOpticalDepth(ivec2 items, vec3 origin, vec3 dir, float t) {
    float sum = 0.0;
    for (int k = items.x; k < items.x + items.y; ++k) {
        GpuParticle p = particles[impostorItems[k].x];
        Chord c = chordOf(origin, dir, p.positionRadius.xyz, p.positionRadius.w);
        if (c.halfChord <= 0.0) continue;
        sum += p.albedoSigma.w * chordIntegral(c, p.positionRadius.w, max(-c.halfChord, -c.tClosest), t - c.tClosest);
    }
    return sum;
}

// The share of the block's optical depth along the ray that lies in front of ray distance t, from
// its own particles (the exact kernels, as the reference integrates them). The impostor's depth
// profile is a two-moment fit: where the mesh cuts a block of several particles it misplaces the
// cut by up to a particle. Negative when the block's particles are not listed.
float listedMassBefore(ivec2 items, vec3 origin, vec3 dir, float t) {
    if (items.y <= 0) return -1.0;
    float total = listedOpticalDepth(items, origin, dir, 1e30);
    return total > 0.0 ? clamp(listedOpticalDepth(items, origin, dir, t) / total, 0.0, 1.0) : -1.0;
}

// A profile's share of mass in front of ray distance t, with the erf at its ends taken once: the
// exact build's order factor (block_order.glsl) reads its neighbours' at every shading point.
struct ProfileCdf {
    float front;
    float back;
    float mean;
    float scale;  // 1/(√2·deviation); 0: uniform over [front, back]
    float lo;     // erf at the front and at the back
    float hi;
};

ProfileCdf profileCdf(BlockProfile p) {
    if (p.deviation > 0.0) {
        float scale = 1.0 / (p.deviation * 1.41421356);
        float lo = erfApprox((p.front - p.mean) * scale), hi = erfApprox((p.back - p.mean) * scale);
        // Far in one tail the erf difference vanishes in float; uniform is then the better guess.
        if (hi - lo > 1e-4) return ProfileCdf(p.front, p.back, p.mean, scale, lo, hi);
    }
    return ProfileCdf(p.front, p.back, p.mean, 0.0, 0.0, 0.0);
}

float cdfMassBefore(ProfileCdf c, float t) {
    if (t <= c.front) return 0.0;
    if (t >= c.back) return 1.0;
    if (c.scale > 0.0) return clamp((erfApprox((t - c.mean) * c.scale) - c.lo) / (c.hi - c.lo), 0.0, 1.0);
    return (t - c.front) / (c.back - c.front);
}

// The profile reaching `tails` further in front and behind, where its kernels' tails lie past
// [front, back]; a profile without spread (uniform) keeps its ends.
BlockProfile widenedByTails(BlockProfile p, vec2 tails) {
    if (p.deviation > 0.0) {
        p.front -= tails.x;
        p.back += tails.y;
    }
    return p;
}

// Share of the profile's mass in front of ray distance t.
float profileMassBefore(BlockProfile p, float t) {
    if (t <= p.front) return 0.0;
    if (t >= p.back) return 1.0;
#ifdef BLOCK_EXACT_CUT
    if (p.listed.y > 0) {
        float lo = listedOpticalDepth(p.listed, p.origin, p.dir, p.front), hi = listedOpticalDepth(p.listed, p.origin, p.dir, p.back);
        if (hi - lo > 0.0) return clamp((listedOpticalDepth(p.listed, p.origin, p.dir, t) - lo) / (hi - lo), 0.0, 1.0);
    }
#endif
    return cdfMassBefore(profileCdf(p), t);
}

// localLightSegment (local_light_segment.glsl) for a block's visible segment [t0, t1] (ray
// parameters) of optical depth τ. A lamp's peak weighs the density right at the lamp, which no
// profile along the whole ray knows, so the block's own particles listed around the lamp
// (lamp_neighbourhood.glsl) give their exact extinction and attenuation, over their whole chords
// (a block's [front, back] covers only ±√3·R/3 of each particle); the rest of its optical depth is
// spread uniformly over [t0, t1] outside the list's ball, and the other blocks' attenuation is
// made exact there as in particles mode. T is read at every node: a block spans many particles,
// so the light's transmittance changes across the segment. Returns J.
float blockLocalLightSegment(vec3 origin, vec3 dir, float t0, float t1, float tau, int i, GpuParticle block, ivec2 items,
                             LayerOrder layer) {
    float alpha = oneMinusExpNeg(tau);
    if (!(alpha > 0.0) || !(t1 > t0)) return 0.0;
    vec2 span = lampLayerSpan(i, origin, dir, layer);
    vec2 lit = spotConeInterval(i, origin, dir, Chord(0.0, 0.0, 0.0), min(t0, span.x), max(t1, span.y));
    float t[LAMP_NODES], f[LAMP_NODES];
    // The segment's middle and half length stand for the kernel's centre and radius (a third of the
    // particles' mean radius darkens the lamp's surroundings: the block's uniform rest has edges).
    if (!lampQuadrature(i, origin, dir, lit, 0.5 * (t0 + t1), 0.5 * (t1 - t0), t, f)) return 0.0;
    float extinction[LAMP_NODES], inFront[LAMP_NODES], listed[LAMP_NODES], logFactor[LAMP_NODES];
    float rest = max(tau - lampLayerMass(i, origin, dir, t, layer, extinction, inFront, listed), 0.0) / (t1 - t0);
    lampOrderCorrection(i, origin, dir, t, layer, logFactor);
    vec3 lightPos = lights[i].position.xyz;
    float sum = 0.0;
    for (int j = 0; j < LAMP_NODES; ++j) {
        vec3 x = origin + dir * t[j];
        bool inBlock = t[j] >= t0 && t[j] <= t1;
        f[j] *= lightShape(i, x) * (extinction[j] + (inBlock ? (1.0 - listed[j]) * rest : 0.0));
        if (f[j] <= 0.0) continue;
        float ownInFront = inFront[j] + rest * clamp(t[j] - t0, 0.0, t1 - t0);
        float towardsLight = blockLightDepth(i, x, items, block);
        f[j] *= exp(logFactor[j] - ownInFront - towardsLight) * lampMeshVisibility(i, x);
        sum += f[j] * phaseValue(block.extra.x, block.emissionG.w, normalize(lightPos - x), dir);
    }
    return sum / alpha;
}

// segmentVisibility for a block's segment [front, back] of the ray: the lit fraction is the lit
// share of the block's mass along the ray (BlockProfile).
float blockSegmentVisibility(int i, vec3 origin, vec3 dir, BlockProfile profile, float t) {
    float soft, crossing;
    bool litInFront;
    if (!meshShadowCrossing(i, origin, dir, profile.front, t, profile.back, soft, crossing, litInFront)) return soft;
    float before = profileMassBefore(profile, crossing);  // share of the mass in front of the crossing
    return clamp(litInFront ? before : 1.0 - before, 0.0, 1.0);
}

// A block is shaded at this many points along its visible segment, weighted by the profile's mass:
// one point misses how the light changes across a block (its own shadow, the mesh's), and at two the
// smooth profile's errors and the compositing order's cancel. The BLOCK_EXACT_SHADING build, which
// corrects the order (block_order.glsl), converges with more points instead (exactShadingPieces).
const int BLOCK_SHADING_PIECES = 2;
#ifdef BLOCK_EXACT_SHADING
const int MAX_SHADING_PIECES = 16;
#else
const int MAX_SHADING_PIECES = BLOCK_SHADING_PIECES;
#endif

// The exact build's piece count: one per 0.5 of optical depth along the ray, the block's own and
// its overlapping neighbours' within its segment (`neighbours`), 4 to 16. The order factor varies across a piece as
// the neighbours' mass in front of it does, and its value at one point misses its mean (Jensen's
// gap), so dense overlaps need thin pieces.
int exactShadingPieces(float tau, float neighbours) { return clamp(int(ceil((tau + neighbours) / 0.5)), 4, MAX_SHADING_PIECES); }

// Table nodes per piece (listedDepthTable); the shading point is interpolated between them. Four
// erred least in the hardest seam band (docs/design-notes.md).
const int LISTED_SUBNODES = 4;
const int MAX_LISTED_NODES = MAX_SHADING_PIECES * LISTED_SUBNODES + 1;

// The listed particles' optical depth from the eye to each of `count` ascending ray distances
// `node`, in one walk over them (a chord per particle, not one per distance): bisection alone
// walks them again at every step of every piece.
void listedDepthTable(ivec2 items, vec3 origin, vec3 dir, float node[MAX_LISTED_NODES], int count, out float depth[MAX_LISTED_NODES]) {
    for (int j = 0; j < count; ++j) depth[j] = 0.0;
    for (int k = items.x; k < items.x + items.y; ++k) {
        GpuParticle p = particles[impostorItems[k].x];
        float radius = p.positionRadius.w;
        Chord c = chordOf(origin, dir, p.positionRadius.xyz, radius);
        float lo = max(-c.halfChord, -c.tClosest);  // the medium starts at the eye
        if (!(c.halfChord > lo)) continue;
        float sk = sqrt(KERNEL_FALLOFF) / radius;
        float scale = p.albedoSigma.w * exp(-sk * sk * c.b2);
        float whole = scale * gaussianSegment(sk, lo, c.halfChord);
        for (int j = 0; j < count; ++j) {
            float u = node[j] - c.tClosest;
            if (u > lo) depth[j] += u >= c.halfChord ? whole : scale * gaussianSegment(sk, lo, u);
        }
    }
}

// Where in the table's span [node[first], node[first + LISTED_SUBNODES]] the optical depth from
// its start reaches the e^−v-weighted mean of what the span holds (shadingDepthFraction), as
// particles mode places a particle's shading point (chordShadingPoint): linear between the nodes
// that hold it, bisected first while they hold more than MAX_LINEAR_DEPTH. A dense particle's
// point lies within its first unit of optical depth, which one interval can overshoot by far.
const float MAX_LINEAR_DEPTH = 0.2;
float tableShadingPoint(float node[MAX_LISTED_NODES], float depth[MAX_LISTED_NODES], int first, vec2 span, ivec2 items, vec3 origin,
                        vec3 dir) {
    float inSpan = depth[first + LISTED_SUBNODES] - depth[first];
    if (!(inSpan > 0.0)) return 0.5 * (span.x + span.y);
    float target = depth[first] + shadingDepthFraction(inSpan) * inSpan;
    int j = first;
    while (j + 1 < first + LISTED_SUBNODES && depth[j + 1] < target) ++j;
    float lo = node[j], hi = node[j + 1], atLo = depth[j], atHi = depth[j + 1];
    for (int it = 0; it < 20 && atHi - atLo > MAX_LINEAR_DEPTH; ++it) {
        float mid = 0.5 * (lo + hi), atMid = listedOpticalDepth(items, origin, dir, mid);
        if (atMid < target) {
            lo = mid;
            atLo = atMid;
        } else {
            hi = mid;
            atHi = atMid;
        }
    }
    return mix(lo, hi, atHi > atLo ? clamp((target - atLo) / (atHi - atLo), 0.0, 1.0) : 0.5);
}

// A block's segment cut into pieces along the ray: each piece's extent, shading point, optical
// depth and weight (its own opacity behind the pieces in front of it, by the profile's mass in it).
struct BlockPieces {
    int count;
    vec2 span[MAX_SHADING_PIECES];
    float at[MAX_SHADING_PIECES];
    float weight[MAX_SHADING_PIECES];
    float tau[MAX_SHADING_PIECES];
};

// The kernels' tails reach past [front, back] (which holds each particle's ±√3·R/3): where a
// shadow boundary crosses them, the lit share counts them, as the reference does. Equal shares
// would put a dense core's light in its thin tails, so each piece's weight follows the profile.
// A block of lumps the slices do not resolve (the BLOCK_OWN_PARTICLES build) and the exact shading
// place the pieces and their points by the listed particles (`listed`).
BlockPieces blockPieces(vec3 origin, vec3 dir, BlockProfile profile, vec2 tails, float tau, ivec2 items, int pieces, bool listed) {
    BlockPieces p;
    p.count = pieces;
    float t0 = profile.front, t1 = profile.back;
    float pieceLength = (t1 - t0) / float(pieces);
    float alpha = oneMinusExpNeg(tau);
    BlockProfile wide = widenedByTails(profile, tails);
    for (int k = 0; k < pieces; ++k) {
        float pieceFront = t0 + float(k) * pieceLength;
        p.span[k] = vec2(k == 0 ? wide.front : pieceFront, k + 1 == pieces ? wide.back : pieceFront + pieceLength);
    }
    // The listed particles' optical depth at each piece's ends and LISTED_SUBNODES − 1 points between.
    float node[MAX_LISTED_NODES], depth[MAX_LISTED_NODES];
    int nodes = 0;
    if (listed) {
        for (int k = 0; k < pieces; ++k)
            for (int j = 0; j < LISTED_SUBNODES; ++j)
                node[nodes++] = max(mix(p.span[k].x, p.span[k].y, float(j) / float(LISTED_SUBNODES)), 0.0);
        node[nodes++] = max(wide.back, 0.0);
        listedDepthTable(items, origin, dir, node, nodes, depth);
    }
    float listedTotal = listed ? depth[nodes - 1] - depth[0] : 0.0;
    float before = 0.0;  // the profile's share of the block's optical depth in front of piece k
    for (int k = 0; k < pieces; ++k) {
        float pieceFront = t0 + float(k) * pieceLength;
        float after = k + 1 == pieces ? 1.0 : profileMassBefore(wide, p.span[k].y);
        // The medium starts at the eye (a piece's kernel tails reach behind it when the camera is
        // inside), and the pieces' shares are the listed particles' too: a cut at the eye bends the
        // profile's moments, and its tails would reach behind the eye.
        if (listed) {
            p.span[k].x = max(p.span[k].x, 0.0);
            if (k + 1 < pieces && listedTotal > 0.0) after = clamp((depth[(k + 1) * LISTED_SUBNODES] - depth[0]) / listedTotal, 0.0, 1.0);
        }
        float share = max(after - before, 0.0);
        p.at[k] = listed ? tableShadingPoint(node, depth, k * LISTED_SUBNODES, p.span[k], items, origin, dir) : pieceFront + shadingDepthFraction(tau * share) * pieceLength;
        p.tau[k] = tau * share;
        p.weight[k] = alpha > 0.0 ? oneMinusExpNeg(tau * share) * exp(-tau * before) / alpha : share;
        before = after;
    }
    return p;
}

// Light i from a distant lamp or the sun over the pieces, each at its shading point. With `own`
// the light's transmittance is integrated over each piece (layerTransmittance) from the listed
// particles' exact optical depth: a dense lump's light changes too steeply across a piece for one
// point to stand for it. A smooth block keeps the slices' transmittance at the point. Adds to
// `scattered` piece by piece (the sum's order is the frame's).
void addBlockPiecesLight(inout vec3 scattered, int i, vec3 origin, vec3 dir, BlockPieces p, BlockProfile wide,
                         float orderFactor[MAX_SHADING_PIECES], GpuParticle block, ivec2 items, bool own) {
    BlockProfile piece = wide;
    for (int k = 0; k < p.count; ++k) {
        piece.front = p.span[k].x;
        piece.back = p.span[k].y;
        float t = p.at[k];
        float visibility = lights[i].spot.z >= 0.0 ? blockSegmentVisibility(i, origin, dir, piece, t) : 1.0;
        vec3 x = origin + dir * t;
        float transmittance = exp(-mediumOpticalDepth(i, x));
        if (own) {
            float atX = blockLightDepth(i, x, items, block);
            float vBar = shadingDepthFraction(p.tau[k]) * p.tau[k];
            transmittance = vBar > 1e-4 && p.tau[k] > 1e-4
                ? layerTransmittance(blockLightDepth(i, origin + dir * p.span[k].x, items, block), atX, vBar, p.tau[k])
                : exp(-atX);
        }
        scattered += p.weight[k] * orderFactor[k] * scatteredLight(i, x, dir, block, visibility, transmittance);
    }
}

// The source of a block's visible segment [profile.front, profile.back] of optical depth τ, whose
// kernels reach `tails` further in front and behind (0 where the segment is cut), for compositing it
// as one layer: every light but point and spot lights near the segment or whose cone's edge crosses it at
// `pieces` points (at most MAX_SHADING_PIECES), one per piece of equal length, each holding the
// depth profile's share of τ and weighted by the share of the block's light it sends to the front,
// with the mesh visibility taken over the piece; those lamps are integrated over the whole of it
// (blockLocalLightSegment: 1/d² across a block spans far more than across one particle, and one
// shading point misses most of a lamp's glow). `exact` (the BLOCK_EXACT_SHADING build only): the
// pieces and their points from the listed particles, and the compositing order corrected
// (blockOrderLogFactor).
vec3 blockSegmentSource(vec3 origin, vec3 dir, BlockProfile profile, vec2 tails, float tau, GpuParticle block, ivec2 items,
                        LayerOrder layer, int pieces, bool exact) {
    float t0 = profile.front, t1 = profile.back;
    bool own = kOwnParticles && items.y > 0;
    bool listed = (kOwnParticles || exact) && items.y > 0;
    BlockPieces p = blockPieces(origin, dir, profile, tails, tau, items, pieces, listed);
    // What the other blocks' compositing order leaves wrong at each piece's point (block_order.glsl),
    // for every light, the ambient and the emission alike.
    float orderFactor[MAX_SHADING_PIECES];
    float weighted = 1.0;  // the pieces' weights times their order factors
    for (int k = 0; k < pieces; ++k) orderFactor[k] = 1.0;
#ifdef BLOCK_EXACT_SHADING
    if (exact) {
        weighted = 0.0;
        for (int k = 0; k < pieces; ++k) {
            orderFactor[k] = exp(blockOrderLogFactor(p.at[k]));
            weighted += p.weight[k] * orderFactor[k];
        }
    }
#endif
#ifdef MEDIA_MULTIPLE  // the environment at each piece's point, as the lights
    vec3 scattered = vec3(0.0);
    for (int k = 0; k < pieces; ++k) scattered += (p.weight[k] * orderFactor[k]) * ambientSource(origin + dir * p.at[k], dir, block);
#else
    vec3 scattered = frame.ambient.rgb * weighted;
#endif
    float radius = block.positionRadius.w;
    BlockProfile wide = widenedByTails(profile, tails);
    for (int i = 0; i < frame.counts.x; ++i) {
#ifdef MEDIA_LOCAL_LIGHTS  // block_composite_pass.cpp builds this only for frames with point or spot lights
        if (lights[i].direction.w > 0.5) {
            float tNearest = clamp(dot(lights[i].position.xyz - origin, dir), t0, t1);
            bool nearLamp = distance(origin + dir * tNearest, lights[i].position.xyz) < (t1 - t0) + 2.0 * radius;
            vec2 lit = spotConeInterval(i, origin, dir, Chord(0.0, 0.0, 0.0), t0, t1);
            if (nearLamp || lit.x > t0 || lit.y < t1) {
                scattered += lights[i].radiance.rgb * blockLocalLightSegment(origin, dir, t0, t1, tau, i, block, items, layer);
                continue;
            }
        }
#endif
        addBlockPiecesLight(scattered, i, origin, dir, p, wide, orderFactor, block, items, own);
    }
    return block.albedoSigma.rgb * scattered + block.emissionG.rgb * weighted;
}
