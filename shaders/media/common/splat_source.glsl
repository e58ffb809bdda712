// The source J a splat's particle sends along this pixel's ray (particle_splats.frag,
// sheets/sheet_splats.frag): the lighting pass's fit (particle_lighting.comp), with the sun's phase
// function and the lamps (MEDIA_FRAGMENT_LAMPS) at the pixel's own ray, towards the fog colour.
// Needs common/math, frame, lights, media optics, kernel_table, particle_light_layout and
// splat_varyings (as in); with MEDIA_FRAGMENT_LAMPS also slices, spot_cone and lamp_quadrature
// (with SPLAT_LAMP_ORDER particle_data and lamp_neighbourhood), with it or MEDIA_MESH_CROSSINGS
// light_views and mesh_shadow.
#ifdef MEDIA_FRAGMENT_LAMPS
// Lamp `light`'s light scattered by the particle's visible segment [lo, hi] of the ray (u from the
// closest point), per unit albedo and radiance, as the layer's source: σ∫ρ(u)e^−τ(u)·S(u)du / α
// with τ(u) the particle's own optical depth in front of u and S = shape·phase·V·T/d² (V the mesh
// shadow map's visibility, T the slices' transmittance from the lamp).

// Where the ray passes the lamp within two deviations, 1/d² peaks far more sharply than the kernel
// varies: the exact tier's quadrature (lamp_quadrature.glsl) over the part inside a spot's cone,
// each node with its own T and e^−τ (inside a dense particle both fall steeply away from the lamp).
// With SPLAT_LAMP_ORDER (particle splats, one particle a composited layer) each node's light around
// the peak also takes the exact attenuation by the lamp's other listed neighbours
// (lamp_neighbourhood.glsl): compositing order dims a neighbour's light by whole particles across
// the lamp's peak (a lamp in a τ 3 cloud errs 42% without it).
#ifdef SPLAT_LAMP_ORDER
// The order's log factors (lampOrderCorrection's) at the nodes around the lamp's peak only: the far
// pieces' nodes lie where the kernel's bulk is and the list is not complete (the τ 3 cloud 7.6% so,
// 8.3% with them). One neighbour at a time, its interval's ends' erf taken once: one erf a node
// (campfire's fast splats pay 3.5 ms for the order; 13 ms with every node and its own erfs).
void peakOrder(int light, vec3 origin, vec3 dir, LampNodes q, float tSurface, bool near, out float order[LAMP_NEAR_NODES]) {
    float t[LAMP_NEAR_NODES];
    for (int j = 0; j < LAMP_NEAR_NODES; ++j) {
        order[j] = 0.0;
        t[j] = lampNode(q, j).x;
    }
    LampList list = lampList(light);
    LayerOrder layer = LayerOrder(vLayer.x, vLayer.y, tSurface, 1e30);
    for (uint n = 0u; n < (near ? list.count : 0u); ++n) {
        LampNeighbour neighbour = lampNeighbour(list, n, origin, dir, layer);
        if (neighbour.valid) addPeakLogFactors(neighbour, t, order);
    }
    for (int j = 0; j < LAMP_NEAR_NODES; ++j) order[j] = lampLogFactorAt(list, light, origin + dir * t[j], order[j]);
}

// order[j] for the quadrature loop's node j, selected, not indexed (lampNode says why).
float nodeOrder(float order[LAMP_NEAR_NODES], int j) {
    float picked = order[0];
    for (int m = 1; m < LAMP_NEAR_NODES; ++m) picked = j == m ? order[m] : picked;
    return picked;
}
#endif

// A lamp's mesh shadow tap and slice optical depth at x. MEDIA_POINT_LAMPS: every lamp is a point
// light, whose six views the lookups then know, reading no view's matrices (common/light_views.glsl).
#ifdef MEDIA_POINT_LAMPS
float lampVisibilityTap(int light, vec3 x, float softness) { return meshVisibilityTapOf(light, 6, x, softness); }
float lampOpticalDepth(int light, vec3 x) { return mediumOpticalDepthOf(light, 6, x); }
#else
float lampVisibilityTap(int light, vec3 x, float softness) { return meshVisibilityTap(light, x, softness); }
float lampOpticalDepth(int light, vec3 x) { return mediumOpticalDepth(light, x); }
#endif

// Elsewhere S varies slowly over the segment and is taken at the shading point p: the quadrature
// loop's first pass, which every lane runs, evaluates it there instead of at its first node (one
// slice fetch and one shadow tap a fragment fewer).
float lampSource(int light, vec3 origin, vec3 dir, float tc, float lo, float hi, float tSurface, float beta, float alpha, vec3 p) {
    float radius = vCentreRadius.w;
    vec2 lit = spotConeInterval(light, origin, dir, Chord(tc, 0.0, 0.0), lo, hi);
    if (!(lit.y > lit.x)) return 0.0;
    vec3 lamp = lights[light].position.xyz;
    vec3 toLamp = lamp - origin;
    float uLamp = dot(toLamp, dir) - tc;
    float s = radius / 3.0;
    float b = length(toLamp - (uLamp + tc) * dir);
    // A spot's cone edge that cuts the segment lights part of it only: the quadrature there too.
    bool cut = lit.x > lo || lit.y < hi;
    bool near = (cut || (b < 2.0 * s && uLamp > lo - 2.0 * s && uLamp < hi + 2.0 * s)) && alpha > 0.0;
    LampNodes q = lampNodes(light, origin, dir, lit + tc, tc, radius);
#ifdef SPLAT_LAMP_ORDER
    float order[LAMP_NEAR_NODES];
    peakOrder(light, origin, dir, q, tSurface, near, order);
#endif
    float k = KERNEL_FALLOFF / (radius * radius), entry = kernelSegment(beta, lo / radius), sum = 0.0, atP = 0.0;
    // A loop, so llvmpipe leaves it after one pass where no lane is near (an if runs under a mask
    // whatever the lanes, and the compiler turns a loop it can prove runs at most once into one).
    int j = 0;
    do {
        vec2 node = lampNode(q, j);
        float u = node.x - tc;
        vec3 x = near ? origin + dir * node.x : p;
        vec3 toX = lamp - x;
        float d2 = max(dot(toX, toX), 1e-12);
        // Near the lamp its light comes from within about its distance, not from the whole kernel.
        float visibility = lights[light].spot.z >= 0.0 ? lampVisibilityTap(light, x, near ? 0.1 * sqrt(d2) : radius / 3.0) : 1.0;
        float lit_ = lightShape(light, x) * phaseValue(vPhase.x, vPhase.y, toX * inversesqrt(d2), dir) * visibility;
        float depth = lampOpticalDepth(light, x);
        atP = lit_ * exp(-depth) / d2;  // read only where not near: the first pass's, at p
        depth += vSigma * radius * max(kernelSegment(beta, u / radius) - entry, 0.0);
#ifdef SPLAT_LAMP_ORDER
        if (j < LAMP_NEAR_NODES) depth -= nodeOrder(order, j);
#endif
        sum += node.y * exp(-k * u * u - depth) * lit_;
    } while (++j < (near ? LAMP_NODES : 0));
    return near ? vSigma * exp(-k * (radius * radius * beta * beta)) * sum / alpha : atP;
}
#endif

#ifdef MEDIA_MESH_CROSSINGS
// The sun's mesh visibility over this ray's visible segment [lo, hi] of a particle that a mesh
// crosses (the lighting pass flags it by negating vSun.rgb and fits the medium's transmittance
// alone): a fit smooth across the billboard would carry the lit side's light across the mesh into
// its shadow. As in the reference, the share of the segment's kernel mass on the lit side: the
// occluder's depth margin, tapped a deviation either side of the mass's centroid, is taken as
// linear along the ray (a locally flat occluder), which places the boundary without the exact
// tier's bisection: two shadow-map taps.
float crossedSunVisibility(vec3 origin, vec3 dir, float tc, float beta2, float tSurface) {
    float radius = vCentreRadius.w;
    float h = radius * sqrt(max(1.0 - beta2, 0.0));
    float lo = max(-h, -tc), hi = min(h, tSurface - tc);
    if (!(hi > lo)) return 1.0;
    // The kernel along the ray is exp(−(sk·u)²): its mass and centroid over [lo, hi] and the mass in
    // front of the boundary share the ends' exponentials and erfc tails (three exp in all; llvmpipe
    // runs every branch, so separate gaussianSegment calls cost five each).
    float sk = sqrt(KERNEL_FALLOFF) / radius;
    float xLo = sk * lo, xHi = sk * hi;
    float eLo = exp(-xLo * xLo), eHi = exp(-xHi * xHi);
    float gLo = erfcPolynomial(abs(xLo)) * eLo;
    float total = erfDifference(xLo, gLo, xHi, erfcPolynomial(abs(xHi)) * eHi);
    if (!(total > 0.0)) return 1.0;
    // ∫u·e^−(sk·u)² du over ∫e^−(sk·u)² du
    float middle = clamp((eLo - eHi) / (sk * 2.0 * HALF_SQRT_PI * total), lo, hi);
    float spread = min(radius / 3.0, 0.25 * (hi - lo));
    float a = max(middle - spread, lo), b = min(middle + spread, hi);
    vec3 base = origin + dir * tc;
    // The sun is directional: one view, whose count the lookups then know.
    float ma = meshShadowMarginOf(uFragmentSun, 1, base + dir * a), mb = meshShadowMarginOf(uFragmentSun, 1, base + dir * b);
    if ((ma > 0.0) == (mb > 0.0) || !(b > a)) return ma > 0.0 ? 1.0 : 0.0;
    float xCross = sk * clamp(a + (b - a) * ma / (ma - mb), lo, hi);
    float before = erfDifference(xLo, gLo, xCross, erfcPolynomial(abs(xCross)) * exp(-xCross * xCross)) / total;  // the mass in front of the boundary
    return clamp(ma > 0.0 ? before : 1.0 - before, 0.0, 1.0);
}
#endif

// The sun's phase at this pixel's own ray (g = 0.99 peaks within a few pixels), with its forward
// peak's orders in the multiple model (peak_orders.glsl) for the fitted transport e^−τ.
float sunPhase(vec3 toLight, vec3 dir, float transport) {
#ifdef MEDIA_MULTIPLE
    return litPhase(vPhase.x, vPhase.y, vPeakAlbedo, transport, toLight, dir);
#else
    return phaseValue(vPhase.x, vPhase.y, toLight, dir);
#endif
}

// tc: the ray's distance to its closest approach to the centre, perp the centre's offset from
// it, beta (beta2) that offset (squared) in radii; tSurface: where the ray meets the scene;
// alpha: the opacity of the particle's whole visible segment.
vec3 splatSource(vec3 origin, vec3 dir, float tc, vec3 perp, float beta, float beta2, float tSurface, float alpha) {
    float radius = vCentreRadius.w;
#ifdef SPLAT_CONSTANT
    vec4 fit = vSource;
#else
    vec4 fit = vSource + (vFit[0] + vFit[1] * beta2) * beta2 + vFit[2] * (vCorner.x * vCorner.x * vCorner.x) +
               vFit[3] * (vCorner.y * vCorner.y * vCorner.y);
#endif
    vec3 source = max(fit.rgb, vec3(0.0));
    float sunTransport = max(fit.a, 0.0);
#ifdef MEDIA_MESH_CROSSINGS
    // A variant of its own: llvmpipe runs this for every fragment, crossed or not (a branch or a
    // loop's first pass runs under a mask whatever the lanes).
    if (vCrossed != 0) sunTransport *= crossedSunVisibility(origin, dir, tc, beta2, tSurface);
#endif
    if (uFragmentSun >= 0)
        source += abs(vSun.rgb) * (sunPhase(-lights[uFragmentSun].direction.xyz, dir, sunTransport) * sunTransport);
#ifdef MEDIA_FRAGMENT_LAMPS
    float h = sqrt(max(radius * radius - dot(perp, perp), 0.0));
    float lo = max(-h, -tc), hi = min(h, tSurface - tc);
    vec3 p = origin + dir * (tc - vSun.a);
    // The lamps are listed first (this variant has at least one): as many passes as lamps.
    int k = 0;
    do {
        int light = uFragmentLamps[k];
        source += vAlbedo * lights[light].radiance.rgb * lampSource(light, origin, dir, tc, lo, hi, tSurface, beta, alpha, p);
    } while (++k < MAX_FRAGMENT_LAMPS && uFragmentLamps[min(k, MAX_FRAGMENT_LAMPS - 1)] >= 0);
#endif
    return mix(frame.fogColor.rgb, source, vFog);
}
