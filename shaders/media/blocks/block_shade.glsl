// One block's light along one view ray from its impostor sample (blocks mode's "super-particle",
// Umenhoffer and Szirmay-Kalos §2): block_composite.frag shades it per media texel, and
// block_impostor_lighting.frag once per impostor texel with no surface on the ray. Needs
// block_data, block_lighting, block_order and, in the BLOCK_EXACT_SHADING build, the composite's
// uImpostorDepths and uImpostorMoments.

// What a block adds to one ray: its premultiplied radiance and opacity (alpha 0: nothing).
struct BlockShade {
    vec3 source;  // radiance scattered or emitted towards the eye per unit opacity
    float alpha;
};

// The share of a block's optical depth along the ray (origin, dir) in front of its opaque surface at
// ray distance tSurface: exact from the block's own particles where the surface lies among them,
// else from the depth profile the impostor's moments give (block_lighting.glsl blockProfile), which
// also shapes the shading. 0 where the block lies wholly behind the surface.
float blockShareBefore(BlockTile tile, ImpostorSample s, vec3 origin, vec3 dir, float tSurface, out BlockProfile profile, out bool cut) {
    // [front, back] holds each particle's ±√3·R/3 (block_impostors.frag); its kernel reaches R.
    // The tile knows only the block's mean radius: 1.5× it covers members up to that size, and a
    // larger member's far tail takes the profile's cut.
    float reach = blockKernelReach(tile.centreRadius.w);
    float momentOrigin = frameOrthographic() ? dot(tile.centreRadius.xyz, frame.cameraForward.xyz) : length(tile.centreRadius.xyz);
    profile = blockProfile(s.front, s.back, momentOrigin, s.sums3.xy / s.tau);
    cut = tSurface < s.back + reach;
    if (tSurface <= s.front - reach) return 0.0;
    // The exact cut walks the block's particles; the build without it (block_composite_pass.cpp
    // draws with it only the blocks a mesh comes near) keeps the profile's cut for safety.
#ifdef BLOCK_EXACT_CUT
    float share = cut ? listedMassBefore(ivec2(tile.instance.zw), origin, dir, tSurface) : 1.0;
    return share < 0.0 ? profileMassBefore(profile, tSurface) : share;
#else
    return cut ? profileMassBefore(profile, tSurface) : 1.0;
#endif
}

// Block `block` (x: the block, y: its rank back to front) seen along the ray (origin, dir) at view
// NDC `ndc`, whose opaque surface lies at ray distance tSurface (1e30: none). `seam` weighs the
// exact shading against the smooth one in the BLOCK_EXACT_SHADING build.
BlockShade shadeBlock(BlockTile tile, ivec2 block, ImpostorSample s, vec3 origin, vec3 dir, float tSurface, vec2 ndc, float seam) {
    BlockProfile profile;
    bool cut;
    float share = blockShareBefore(tile, s, origin, dir, tSurface, profile, cut);
    float reach = blockKernelReach(tile.centreRadius.w);
    ivec2 items = ivec2(tile.instance.zw);  // (count 0: an instance, whose particles are not listed)
    float tau = s.tau * share;
    float alpha = oneMinusExpNeg(tau);
    if (alpha <= 0.0) return BlockShade(vec3(0.0), 0.0);

    float end = min(s.back, tSurface);
    GpuParticle particle;
    particle.positionRadius = vec4(tile.centreRadius.xyz, tile.centreRadius.w);
    particle.albedoSigma = vec4(s.sums1.yzw / s.tau, 0.0);
    particle.emissionG = vec4(s.sums2.xyz / s.tau, clamp(s.sums2.w / s.tau, -0.999, 0.999));
    particle.extra = vec4(0.0, tile.lampSlices.x, 0.0, 0.0);  // y: blockLightDepth's (block_own_optical_depth.glsl)
    LayerOrder layer = LayerOrder(-1, block.y, tSurface, 1e30);
    // What the light sees of it ends at the surface; a surface just in front of the block cuts
    // only its kernels' tails, which lie within `reach` of it.
    profile.front = end > s.front ? s.front : end - reach;
    profile.back = end;
    vec2 tails = vec2(end > s.front ? reach : 0.0, end < s.back ? 0.0 : reach);  // none past a cut
    // What is left in front of a cut is no longer the normal the moments describe: its own
    // particles say where its mass lies.
#ifdef BLOCK_EXACT_CUT
    if (cut && share > 0.0) {
        profile.origin = origin;
        profile.dir = dir;
        profile.listed = items;
    }
#endif
    vec3 source = vec3(0.0);
#ifdef BLOCK_EXACT_SHADING
    BlockProfile shaded = widenedByTails(profile, tails);  // where blockSegmentSource's shading points lie
    vec2 span = vec2(shaded.front, shaded.back);
    float neighbours = gatherOrderNeighbours(block.x, block.y, ndc, tSurface, span, origin, dir, uImpostorDepths, uImpostorMoments);
    // The exact shading, and where the seam's weight falls off, the smooth one too (a loop, not two
    // calls: one copy of blockSegmentSource's code).
    for (int part = 0; part < (seam < 1.0 ? 2 : 1); ++part) {
        bool exact = part == 0;
        int pieces = exact ? exactShadingPieces(tau, neighbours) : BLOCK_SHADING_PIECES;
        source += (exact ? seam : 1.0 - seam) *
                  blockSegmentSource(origin, dir, profile, tails, tau, particle, ivec2(tile.instance.zw), layer, pieces, exact);
    }
#else
    source = blockSegmentSource(origin, dir, profile, tails, tau, particle, ivec2(tile.instance.zw), layer, BLOCK_SHADING_PIECES, false);
#endif
    return BlockShade(source, alpha);
}
