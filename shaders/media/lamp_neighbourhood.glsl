// Near a point or spot light, the exact attenuation of a composited layer's light
// (media/lamp_neighbourhood.h says why compositing order gets it wrong there). Needs common/frame,
// lights, media/optics, particle_data.
layout(std430, binding = 8) readonly buffer LampNeighbourhoods { uint lampWords[]; };  // uvec4 per light, then uvec2 per neighbour

// Where a particle's layer stands in particles mode's compositing, and how its fragments clip.
struct LayerOrder {
    int particle;   // its index
    int rank;       // its place in the back-to-front draw order
    float tEnd;     // the ray ends there (soft particles: at the opaque surface)
    float tHidden;  // a particle whose closest point lies beyond this is not drawn (classic billboards)
};

const int LAMP_NODES = 8;  // the points of local_light_segment.glsl's quadrature

// For light scattered at each ray parameter t[j], the log of the factor that turns the attenuation
// compositing gives it into the exact e^−(optical depth in front of t): particles drawn after this
// one dim it by all their mass (undo what lies behind t), particles drawn before by none of it
// (apply what lies in front). Per point, not once per layer: the optical depth changes across a
// lamp's peak, and e^x averaged is not e^(x averaged). Exact for the listed neighbours where their
// list is complete, within `reach` of the lamp; faded out from reach/2 so that no ring marks where
// the list ends.
void lampOrderCorrection(int light, vec3 origin, vec3 dir, float t[LAMP_NODES], LayerOrder layer,
                         out float logFactor[LAMP_NODES]) {
    for (int j = 0; j < LAMP_NODES; ++j) logFactor[j] = 0.0;
    uint header = 4u * uint(light);
    uint count = lampWords[header + 1u];
    if (count == 0u) return;
    float reach = uintBitsToFloat(lampWords[header + 2u]);
    uint entries = 4u * uint(frame.counts.x) + 2u * lampWords[header];
    for (uint n = 0u; n < count; ++n) {
        int q = int(lampWords[entries + 2u * n]);
        if (q == layer.particle) continue;  // its own attenuation is already exact
        vec4 pr = particles[q].positionRadius;
        Chord c = chordOf(origin, dir, pr.xyz, pr.w);
        if (c.halfChord <= 0.0 || c.tClosest > layer.tHidden) continue;
        float u0 = max(0.0, c.tClosest - c.halfChord) - c.tClosest;  // as particles.frag clips it
        float u1 = min(layer.tEnd - c.tClosest, c.halfChord);
        if (u1 <= u0) continue;
        float sigma = particles[q].albedoSigma.w;
        bool drawnAfter = int(lampWords[entries + 2u * n + 1u]) > layer.rank;
        for (int j = 0; j < LAMP_NODES; ++j) {
            float split = clamp(t[j] - c.tClosest, u0, u1);
            logFactor[j] += drawnAfter ? sigma * chordIntegral(c, pr.w, split, u1) : -sigma * chordIntegral(c, pr.w, u0, split);
        }
    }
    vec3 lamp = lights[light].position.xyz;
    for (int j = 0; j < LAMP_NODES; ++j)
        logFactor[j] *= 1.0 - smoothstep(0.5 * reach, reach, distance(origin + dir * t[j], lamp));
}
