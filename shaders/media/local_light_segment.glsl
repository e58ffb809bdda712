// A point or spot light's in-scattering integrated over one particle's visible segment of a view
// ray, for the layers that particles mode composites. Evaluating the light at one shading point
// fails in two places the reference resolves along each ray:
//  - near the lamp 1/d² peaks far more sharply than the kernel varies, and the phase angle, the
//    light's transmittance and the particle's own attenuation all change across that peak;
//  - a spot cone's edge crossing a particle lights part of its segment only.
// Both become smooth once the segment is cut to the cone and u = u_l + b·tan φ (u_l the lamp's
// closest approach, b its distance): ∫ f(u)/d² du = (1/b) ∫ f dφ, which Gauss–Legendre handles.
// Needs lights, transmittance, media/optics, media/lamp_neighbourhood.

// The part [a, b] of [lo, hi] (u from the chord's closest point) inside light i's cone: all of it
// for a point light, b < a when the ray misses the cone. The forward nappe is convex, so the inside
// is one interval, bounded by roots of (w·D)² = cos²θ_o |w|² with w = x − apex.
vec2 spotConeInterval(int i, vec3 origin, vec3 dir, Chord c, float lo, float hi) {
    GpuLight L = lights[i];
    if (int(L.direction.w + 0.5) != 2) return vec2(lo, hi);
    float cosOuter = L.spot.x > 0.0 ? -L.spot.y / L.spot.x : 0.0;
    vec3 D = L.direction.xyz;
    vec3 w0 = origin + dir * c.tClosest - L.position.xyz;
    float dD = dot(dir, D), wD = dot(w0, D), c2 = cosOuter * cosOuter;
    float A = dD * dD - c2, B = wD * dD - c2 * dot(w0, dir), C = wD * wD - c2 * dot(w0, w0);
    float cuts[4] = float[](lo, lo, hi, hi);
    if (abs(A) > 1e-7) {
        float disc = B * B - A * C;
        if (disc > 0.0) {
            // The root pair without cancellation: q = −(B + sign(B)√disc), roots q/A and C/q.
            float q = -(B + (B >= 0.0 ? 1.0 : -1.0) * sqrt(disc));
            float r0 = q / A, r1 = abs(q) > 1e-30 ? C / q : r0;
            cuts[1] = clamp(min(r0, r1), lo, hi);
            cuts[2] = clamp(max(r0, r1), lo, hi);
        }
    } else if (abs(B) > 1e-30) {
        cuts[1] = cuts[2] = clamp(-0.5 * C / B, lo, hi);
    }
    float a = hi, b = lo;
    for (int piece = 0; piece < 3; ++piece) {
        if (!(cuts[piece + 1] > cuts[piece])) continue;
        vec3 x = origin + dir * (c.tClosest + 0.5 * (cuts[piece] + cuts[piece + 1])) - L.position.xyz;
        if (dot(x, D) > cosOuter * length(x)) {
            a = min(a, cuts[piece]);
            b = max(b, cuts[piece + 1]);
        }
    }
    return vec2(a, b);
}

// Light i scattered by the particle's segment [lo, hi] towards the camera, as the source J of the
// composited layer (the layer adds α·J, α = 1 − e^−τ over the segment):
//   J = (σ/α) ∫ ρ(u) e^−τs(u) p(θ(u)) E(u) T(u) du over the lit part [a, b],
// τs the particle's own optical depth in front of u, T the light's transmittance through the
// medium, E the light's irradiance (shape/d²). Mesh visibility is left to the caller, at the
// returned u (x: J per unit albedo and radiance, y: where the integrand is centred). Near the lamp
// (`nearLamp`) T is read from the slices at every node and the other layers' attenuation is made
// exact (lamp_neighbourhood.glsl); further away both vary slowly over one particle and the caller
// applies T once.
vec2 localLightSegment(vec3 origin, vec3 dir, Chord c, float radius, float lo, float hi, vec2 lit, int i,
                       GpuParticle particle, bool nearLamp, LayerOrder layer) {
    vec3 lightPos = lights[i].position.xyz;
    vec3 toLight = lightPos - origin;
    float tLight = dot(toLight, dir);
    float b = max(length(toLight - tLight * dir), 1e-4 * radius);
    float uLight = tLight - c.tClosest;
    float phi0 = atan((lit.x - uLight) / b), phi1 = atan((lit.y - uLight) / b);
    float sigma = particle.albedoSigma.w;
    float tau = sigma * chordIntegral(c, radius, lo, hi);
    float alpha = oneMinusExpNeg(tau);
    if (!(alpha > 0.0) || !(phi1 > phi0)) return vec2(0.0, 0.5 * (lit.x + lit.y));
    float k = KERNEL_FALLOFF / (radius * radius);
    const float nodes[4] = float[](0.1834346425, 0.5255324099, 0.7966664774, 0.9602898565);
    const float weights[4] = float[](0.3626837834, 0.3137066459, 0.2223810345, 0.1012285363);
    float mid = 0.5 * (phi0 + phi1), half_ = 0.5 * (phi1 - phi0);
    float u[LAMP_NODES], f[LAMP_NODES], t[LAMP_NODES];
    for (int j = 0; j < LAMP_NODES; ++j) {
        u[j] = uLight + b * tan(mid + float(j % 2 == 0 ? -1 : 1) * half_ * nodes[j / 2]);
        t[j] = c.tClosest + u[j];
        vec3 x = origin + dir * t[j];
        f[j] = weights[j / 2] * exp(-k * (c.b2 + u[j] * u[j])) * lightShape(i, x);
        if (f[j] <= 0.0) continue;
        f[j] *= exp(-sigma * chordIntegral(c, radius, lo, u[j]));
        f[j] *= phaseValue(particle.extra.x, particle.emissionG.w, normalize(lightPos - x), dir);
        if (nearLamp) f[j] *= exp(-mediumOpticalDepth(i, x));
    }
    float logFactor[LAMP_NODES];
    if (nearLamp) lampOrderCorrection(i, origin, dir, t, layer, logFactor);
    float sum = 0.0, weightedU = 0.0;
    for (int j = 0; j < LAMP_NODES; ++j) {
        float w = nearLamp ? f[j] * exp(logFactor[j]) : f[j];
        sum += w;
        weightedU += w * u[j];
    }
    float J = sigma * half_ * sum / (b * alpha);
    return vec2(J, sum > 0.0 ? clamp(weightedU / sum, lo, hi) : clamp(uLight, lo, hi));
}
