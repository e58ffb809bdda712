// A block's own share of the light slices (own_optical_depth.glsl says why a particle's own share
// is made exact where the slices do not resolve it). Block slices hold each block's optical depth
// spread along the light ray by its depth profile (block_light_profile.glsl), so a block of
// particles thinner than the slice spacing or a texel shadows its own lit side with its whole
// optical depth smeared over the interval (a small dense particle beside a lamp goes black). Where
// the slices do not resolve a block's particles, what they hold of the block at p is recomputed
// from its particles as the light impostor and block_slices.frag made it, taken out, and their
// exact optical depth from the light to p put in. The recomputation is exact where the light tile
// has one texel per slice texel (which the atlas gives blocks of particles much smaller than a
// texel, impostor_atlas.cpp tileSizes); elsewhere the tile's bilinear read is approximated by the
// rays of the slice texels. Needs media/own_optical_depth, block_data and block_light_profile.

// The blocks composited with this code (BLOCK_OWN_PARTICLES) are chosen on the CPU
// (planning/block_classification.h blocksOfUnresolvedParticles): at most 64 particles each, which this walks for
// four texel rays at each shading point. llvmpipe would pay for it in every pixel of a draw.
#ifdef BLOCK_OWN_PARTICLES
const bool kOwnParticles = true;
#else
const bool kOwnParticles = false;
#endif

// x: what mediaViewOpticalDepth(v, p) holds of the block's particles `items` (block_slices.frag, read
// back as the slices are); y: their exact optical depth from the light to p. `centreRadius`: the
// block's centre (origin-relative world), about which its light impostor sums its depth moments,
// and its mean particle radius (its tile's); `oneByOne`: a lamp's view holds its particles one by
// one (light_slices.frag), not its impostor.
vec2 ownBlockOpticalDepth(GpuLightView v, vec3 p, ivec2 items, vec4 centreRadius, bool oneByOne) {
    if (oneByOne && v.params.x > 0.5) {
        vec2 sum = vec2(0.0);
        for (int n = items.x; n < items.x + items.y; ++n) {
            GpuParticle q = particles[impostorItems[n].x];
            sum += ownOpticalDepth(v, p, q.positionRadius, q.albedoSigma.w);
        }
        return sum;
    }
    SliceRead r = sliceRead(v, p);
    if (!r.inView) return vec2(0.0);
    vec3 centreView = (v.view * vec4(centreRadius.xyz, 1.0)).xyz;
    float momentOrigin = r.perspective ? length(centreView) : -centreView.z;  // block_data.glsl tileMomentOrigin
    float exact = 0.0, stretch;
    for (int n = items.x; n < items.x + items.y; ++n) {
        GpuParticle q = particles[impostorItems[n].x];
        vec3 c = (v.view * vec4(q.positionRadius.xyz, 1.0)).xyz;
        Chord toP = lightViewChord(r.perspective, sliceReadOwnRay(r), c, q.positionRadius.w, stretch);
        exact += ownDepthUpTo(toP, q.positionRadius.w, q.albedoSigma.w, r.perspective, r.depth * stretch);
    }
    if (!r.holds) return vec2(0.0, exact);
    float smeared = 0.0;
    for (int j = 0; j < 4; ++j) {
        if (!(r.weight[j] > 0.0)) continue;
        // The texel's optical depth, depth moments and [front, back], as block_impostors.frag makes them.
        float tau = 0.0, first = 0.0, second = 0.0, front = 3.0e38, back = -3.0e38;
        for (int n = items.x; n < items.x + items.y; ++n) {
            GpuParticle q = particles[impostorItems[n].x];
            float radius = q.positionRadius.w;
            Chord c = lightViewChord(r.perspective, r.onPlane[j], (v.view * vec4(q.positionRadius.xyz, 1.0)).xyz, radius, stretch);
            if (c.halfChord <= 0.0) continue;
            float lo = max(-c.halfChord, -c.tClosest);  // rays start at the light (or the view plane)
            if (lo >= c.halfChord) continue;
            float t = q.albedoSigma.w * chordIntegral(c, radius, lo, c.halfChord);
            if (!(t > 0.0)) continue;
            vec2 m = chordMoments(c, radius, lo, c.halfChord);
            float mean = c.tClosest + m.x - momentOrigin;
            tau += t;
            first += t * mean;
            second += t * (m.y + mean * mean);
            float extent = min(c.halfChord, 1.7320508 * radius / 3.0);
            front = min(front, c.tClosest + max(lo, -extent));
            back = max(back, c.tClosest + max(extent, lo));
        }
        if (!(tau > 0.0)) continue;
        float mean = first / tau;
        BlockLightProfile profile = blockLightProfile(mean + momentOrigin, sqrt(max(second / tau - mean * mean, 0.0)), front, back,
                                                      blockKernelReach(centreRadius.w), r.perspective);
        float lo = r.firstSlice ? 0.0 : tau * blockLightShare(profile, r.nearPlane * stretch);
        float hi = tau * blockLightShare(profile, r.farPlane * stretch);
        smeared += r.weight[j] * mix(lo, hi, r.f);
    }
    return vec2(smeared, exact);
}

// The medium's optical depth towards light i at a point p of a block (its listed particles
// `items`; block.extra.y: 1 when the lamps' slices hold them one by one): the slices', with the
// block's own share made exact in the BLOCK_OWN_PARTICLES build, drawn for the blocks whose
// particles some view's slices do not resolve (in a view that does, the correction changes little
// and costs the same).
float blockLightDepth(int i, vec3 p, ivec2 items, GpuParticle block) {
    if (!kOwnParticles) return mediumOpticalDepth(i, p);
    int view = lightSliceView(i, p);
    if (view < 0) return 0.0;
    GpuLightView v = mediaSliceViews[view];
    float slices = mediaViewOpticalDepth(v, p);
    if (items.y <= 0) return slices;
    vec2 own = ownBlockOpticalDepth(v, p, items, block.positionRadius, block.extra.y > 0.5);
    return max(slices - own.x, 0.0) + own.y;
}
