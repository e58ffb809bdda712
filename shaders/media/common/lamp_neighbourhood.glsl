// Near a point or spot light, the exact attenuation of a composited layer's light
// (media/lamp_neighbourhood.h says why compositing order gets it wrong there). Needs common/frame,
// lights, media/optics, particle_data.
#include "media/bindings.glsl"
layout(std430, binding = MEDIA_LAMP_NEIGHBOURHOODS_BINDING) readonly buffer LampNeighbourhoods { uint lampWords[]; };  // uvec4 per light, then uvec2 per neighbour

// Where a composited layer (a particle, or a block of them) stands, and how its fragments clip.
struct LayerOrder {
    int particle;   // its index (−1 for a block)
    int rank;       // its place in the back-to-front draw order: listed neighbours of equal rank are its own
    float tEnd;     // the ray ends there (soft particles: at the opaque surface)
    float tHidden;  // a particle whose closest point lies beyond this is not drawn (classic billboards)
};

#include "media/common/lamp_quadrature.glsl"

// Light `light`'s neighbour list: how many, where they start, and the reach within which it is complete.
struct LampList {
    uint count;
    uint entries;
    float reach;
};

LampList lampList(int light) {
    uint header = 4u * uint(light);
    return LampList(lampWords[header + 1u], 4u * uint(frame.counts.x) + 2u * lampWords[header],
                    uintBitsToFloat(lampWords[header + 2u]));
}

// How far each point is inside the part of the reach ball where the list is trusted: 1 within
// reach/2, fading to 0 at reach (so no ring marks where the list ends).
float lampListWeight(LampList list, int light, vec3 x) {
    return list.reach > 0.0 ? 1.0 - smoothstep(0.5 * list.reach, list.reach, distance(x, lights[light].position.xyz)) : 0.0;
}

// For light scattered at each ray parameter t[j], the log of the factor that turns the attenuation
// compositing gives it into the exact e^−(optical depth in front of t): particles drawn after this
// one dim it by all their mass (undo what lies behind t), particles drawn before by none of it
// (apply what lies in front). Per point, not once per layer: the optical depth changes across a
// lamp's peak, and e^x averaged is not e^(x averaged). Exact for the listed neighbours where their
// list is complete, within `reach` of the lamp (lampListWeight).
// Capped: the factor undoes what the layers drawn after this one take away in the blend, and past
// e^50 their transmittance (at most e^−50) leaves nothing a float can give back. Uncapped, a dense
// neighbour's e^τ overflows to inf, and the blend's 0 · inf makes NaN pixels.
const float MAX_LAMP_LOG_FACTOR = 50.0;

// Listed neighbour n of another rank as the layer's ray meets it: its chord, the part of it that is
// drawn [u0, u1] (as particles.frag clips it) and whether it is drawn after the layer; valid is
// false where it changes nothing.
struct LampNeighbour {
    Chord c;
    float radius, sigma, u0, u1;
    bool drawnAfter, valid;
};

LampNeighbour lampNeighbour(LampList list, uint n, vec3 origin, vec3 dir, LayerOrder layer) {
    LampNeighbour q;
    q.valid = false;
    int rank = int(lampWords[list.entries + 2u * n + 1u]);
    if (rank == layer.rank) return q;  // its own attenuation is already exact
    int index = int(lampWords[list.entries + 2u * n]);
    vec4 pr = particles[index].positionRadius;
    q.c = chordOf(origin, dir, pr.xyz, pr.w);
    if (q.c.halfChord <= 0.0 || q.c.tClosest > layer.tHidden) return q;
    q.u0 = max(0.0, q.c.tClosest - q.c.halfChord) - q.c.tClosest;
    q.u1 = min(layer.tEnd - q.c.tClosest, q.c.halfChord);
    q.radius = pr.w;
    q.sigma = particles[index].albedoSigma.w;
    q.drawnAfter = rank > layer.rank;
    q.valid = q.u1 > q.u0;
    return q;
}

// Neighbour q's share of the log factor for light scattered at ray parameter t.
float lampNeighbourLogFactor(LampNeighbour q, float t) {
    float split = clamp(t - q.c.tClosest, q.u0, q.u1);
    return q.drawnAfter ? q.sigma * chordIntegral(q.c, q.radius, split, q.u1) : -q.sigma * chordIntegral(q.c, q.radius, q.u0, split);
}

// lampNeighbourLogFactor added at the quadrature's nodes around the lamp's peak (the splats'), in
// erfs: the interval's ends' taken once, one erf a node, without chordIntegral's short-interval
// quadrature (what it refines is far below what the factor needs).
void addPeakLogFactors(LampNeighbour q, float t[LAMP_NEAR_NODES], inout float sum[LAMP_NEAR_NODES]) {
    float sk = sqrt(KERNEL_FALLOFF) / q.radius;
    float scale = q.sigma * exp(-sk * sk * q.c.b2) * HALF_SQRT_PI / sk;
    float e0 = erfApprox(sk * q.u0), e1 = erfApprox(sk * q.u1);
    for (int j = 0; j < LAMP_NEAR_NODES; ++j) {
        float e = erfApprox(sk * clamp(t[j] - q.c.tClosest, q.u0, q.u1));
        sum[j] += scale * (q.drawnAfter ? e1 - e : e0 - e);
    }
}

// The summed log factor at x, weighted where the list is complete and capped.
float lampLogFactorAt(LampList list, int light, vec3 x, float sum) {
    return min(sum * lampListWeight(list, light, x), MAX_LAMP_LOG_FACTOR);
}

// The factors at each of a quadrature's points t[j] (local_light_segment.glsl, blocks).
void lampOrderCorrection(int light, vec3 origin, vec3 dir, float t[LAMP_NODES], LayerOrder layer,
                         out float logFactor[LAMP_NODES]) {
    for (int j = 0; j < LAMP_NODES; ++j) logFactor[j] = 0.0;
    LampList list = lampList(light);
    if (list.count == 0u) return;
    for (uint n = 0u; n < list.count; ++n) {
        LampNeighbour q = lampNeighbour(list, n, origin, dir, layer);
        if (!q.valid) continue;
        for (int j = 0; j < LAMP_NODES; ++j) logFactor[j] += lampNeighbourLogFactor(q, t[j]);
    }
    for (int j = 0; j < LAMP_NODES; ++j) logFactor[j] = lampLogFactorAt(list, light, origin + dir * t[j], logFactor[j]);
}

// Where the layer's own listed particles lie along the ray (their chords from the eye to
// layer.tEnd); x > y when none does.
vec2 lampLayerSpan(int light, vec3 origin, vec3 dir, LayerOrder layer) {
    LampList list = lampList(light);
    vec2 span = vec2(1e30, -1e30);
    for (uint n = 0u; n < list.count; ++n) {
        if (int(lampWords[list.entries + 2u * n + 1u]) != layer.rank) continue;
        vec4 pr = particles[lampWords[list.entries + 2u * n]].positionRadius;
        Chord c = chordOf(origin, dir, pr.xyz, pr.w);
        float start = max(c.tClosest - c.halfChord, 0.0), end = min(c.tClosest + c.halfChord, layer.tEnd);
        if (c.halfChord > 0.0 && end > start) span = vec2(min(span.x, start), max(span.y, end));
    }
    return span;
}

// The layer's own listed particles along the ray: their extinction σρ at each point, their optical
// depth in front of it (from the eye, clipped at layer.tEnd as the impostor is), and their total.
// A block assumes uniform density, which near a lamp puts mass where the block has none, or too
// little where its particles crowd the lamp; the listed particles are exact there. `listed[j]`:
// how far each point lies where the list is complete (lampListWeight), so where the block's other
// particles have no mass.
float lampLayerMass(int light, vec3 origin, vec3 dir, float t[LAMP_NODES], LayerOrder layer, out float extinction[LAMP_NODES],
                    out float inFront[LAMP_NODES], out float listed[LAMP_NODES]) {
    LampList list = lampList(light);
    for (int j = 0; j < LAMP_NODES; ++j) {
        extinction[j] = 0.0;
        inFront[j] = 0.0;
        listed[j] = lampListWeight(list, light, origin + dir * t[j]);
    }
    float total = 0.0;
    for (uint n = 0u; n < list.count; ++n) {
        if (int(lampWords[list.entries + 2u * n + 1u]) != layer.rank) continue;
        GpuParticle q = particles[lampWords[list.entries + 2u * n]];
        float radius = q.positionRadius.w, sigma = q.albedoSigma.w;
        Chord c = chordOf(origin, dir, q.positionRadius.xyz, radius);
        float u0 = max(-c.halfChord, -c.tClosest), u1 = min(c.halfChord, layer.tEnd - c.tClosest);
        if (c.halfChord <= 0.0 || u1 <= u0) continue;
        total += sigma * chordIntegral(c, radius, u0, u1);
        float k = KERNEL_FALLOFF / (radius * radius);
        for (int j = 0; j < LAMP_NODES; ++j) {
            float u = t[j] - c.tClosest;
            if (u > u0 && u < u1) extinction[j] += sigma * exp(-k * (c.b2 + u * u));
            inFront[j] += sigma * chordIntegral(c, radius, u0, min(u, u1));
        }
    }
    return total;
}
