// A point or spot light's in-scattering integrated over one particle's visible segment of a view
// ray, for the layers that particles mode composites. Evaluating the light at one shading point
// fails in two places the reference resolves along each ray:
//  - near the lamp 1/d² peaks far more sharply than the kernel varies, and the phase angle, the
//    light's transmittance and the particle's own attenuation all change across that peak;
//  - a spot cone's edge crossing a particle lights part of its segment only.
// Both become smooth once the segment is cut to the cone and u = u_l + b·tan φ (u_l the lamp's
// closest approach, b its distance): ∫ f(u)/d² du = (1/b) ∫ f dφ, which Gauss–Legendre handles.
// Needs lights, transmittance, media/optics, media/lamp_neighbourhood and meshVisibilityTap (lighting.glsl).

#include "media/common/spot_cone.glsl"

// The nodes of ∫ f(t)/d(t)² dt over [a, b] = lit for light i, f carrying a kernel centred at ray
// parameter `kernelAt` with radius `radius` (deviation radius/3). Gauss–Legendre in φ with
// t = t_l + b·tan φ (t_l the lamp's closest approach along the ray, b its distance), where 1/d²
// peaks. Where the kernel's centre lies more than two deviations from t_l, its bulk and the
// lamp's peak are integrated apart, split halfway: φ within that reach of t_l, t beyond it, where
// the kernel varies and 1/d² hardly does. φ alone squeezes the far chord into a sliver next to
// ±π/2 with no node in the bulk, and a lamp near a particle's rim glows too bright. Fills the ray
// parameters t[j] and weights w[j] (Jacobian and 1/d² included: Σ w_j f(t_j) ≈ the integral); false
// when the interval is empty. b is at least 1e-4 of the interval (a lamp exactly on the ray).
bool lampQuadrature(int i, vec3 origin, vec3 dir, vec2 lit, float kernelAt, float radius, out float t[LAMP_NODES],
                    out float w[LAMP_NODES]) {
    vec3 toLight = lights[i].position.xyz - origin;
    float tLight = dot(toLight, dir);
    float b = max(length(toLight - tLight * dir), 1e-4 * (lit.y - lit.x));
    float apart = abs(tLight - kernelAt);
    float reach = apart > 2.0 * radius / 3.0 ? 0.5 * apart : 1e30;
    float near0 = clamp(tLight - reach, lit.x, lit.y), near1 = clamp(tLight + reach, lit.x, lit.y);
    bool split = near1 > near0;
    if (!split) {
        near0 = lit.x;
        near1 = lit.y;
    }
    const float nodes[4] = float[](0.1834346425, 0.5255324099, 0.7966664774, 0.9602898565);
    const float weights[4] = float[](0.3626837834, 0.3137066459, 0.2223810345, 0.1012285363);
    float phi0 = atan((near0 - tLight) / b), phi1 = atan((near1 - tLight) / b);
    float mid = 0.5 * (phi0 + phi1), half_ = 0.5 * (phi1 - phi0);
    for (int j = 0; j < LAMP_NEAR_NODES; ++j) {
        t[j] = tLight + b * tan(mid + float(j % 2 == 0 ? -1 : 1) * half_ * nodes[j / 2]);
        w[j] = weights[j / 2] * half_ / b;
    }
    // Three-point Gauss–Legendre in t on each far piece, [lit.x, near0] and [near1, lit.y]; zero
    // weights where there is none.
    const float farNodes[3] = float[](-0.7745966692, 0.0, 0.7745966692);
    const float farWeights[3] = float[](0.5555555556, 0.8888888889, 0.5555555556);
    for (int j = LAMP_NEAR_NODES; j < LAMP_NODES; ++j) {
        int k = j - LAMP_NEAR_NODES;
        bool before = k < 3;
        float a = before ? lit.x : near1, c = before ? near0 : lit.y;
        float h = split && c > a ? 0.5 * (c - a) : 0.0;
        t[j] = 0.5 * (a + c) + h * farNodes[k % 3];
        float u = t[j] - tLight;
        w[j] = farWeights[k % 3] * h / (b * b + u * u);
    }
    return lit.y > lit.x;
}

// The mesh visibility of lamp i at x, one shadow tap per quadrature node. Near a lamp the light
// comes from within about its distance of the ray, not from a whole kernel: a tap softened over the
// kernel's depth (R/3) lets a lamp just under a plate light the medium above it. The depth
// softness left, a tenth of the distance, stays above a cube-map texel's footprint at grazing slopes.
float lampMeshVisibility(int i, vec3 x) {
    return lights[i].spot.z >= 0.0 ? meshVisibilityTap(i, x, 0.1 * distance(x, lights[i].position.xyz)) : 1.0;
}

// Light i scattered by the particle's segment [lo, hi] towards the camera, as the source J of the
// composited layer (the layer adds α·J, α = 1 − e^−τ over the segment):
//   J = (σ/α) ∫ ρ(u) e^−τs(u) p(θ(u)) E(u) T(u) du over the lit part [a, b],
// τs the particle's own optical depth in front of u, T the light's transmittance through the
// medium, E the light's irradiance (shape/d²); x: J per unit albedo and radiance, y: where the
// integrand is centred. Near the lamp (`nearLamp`) T and the mesh visibility are taken at every
// node and the other layers' attenuation is made exact (lamp_neighbourhood.glsl); further away
// all three vary slowly over one particle and the caller applies them once, at y.
vec2 localLightSegment(vec3 origin, vec3 dir, Chord c, float radius, float lo, float hi, vec2 lit, int i,
                       GpuParticle particle, bool nearLamp, LayerOrder layer) {
    float sigma = particle.albedoSigma.w;
    float alpha = oneMinusExpNeg(sigma * chordIntegral(c, radius, lo, hi));
    float t[LAMP_NODES], f[LAMP_NODES];
    if (!(alpha > 0.0) || !lampQuadrature(i, origin, dir, lit + c.tClosest, c.tClosest, radius, t, f))
        return vec2(0.0, 0.5 * (lit.x + lit.y));
    float k = KERNEL_FALLOFF / (radius * radius);
    vec3 lightPos = lights[i].position.xyz;
    for (int j = 0; j < LAMP_NODES; ++j) {
        float u = t[j] - c.tClosest;
        vec3 x = origin + dir * t[j];
        f[j] *= exp(-k * (c.b2 + u * u)) * lightShape(i, x);
        if (f[j] <= 0.0) continue;
        f[j] *= exp(-sigma * chordIntegral(c, radius, lo, u));
        f[j] *= phaseValue(particle.extra.x, particle.emissionG.w, normalize(lightPos - x), dir);
        if (nearLamp) f[j] *= exp(-particleLightDepth(i, x, particle)) * lampMeshVisibility(i, x);
    }
    float logFactor[LAMP_NODES];
    if (nearLamp) lampOrderCorrection(i, origin, dir, t, layer, logFactor);
    float sum = 0.0, weightedT = 0.0;
    for (int j = 0; j < LAMP_NODES; ++j) {
        float w = nearLamp ? f[j] * exp(logFactor[j]) : f[j];
        sum += w;
        weightedT += w * t[j];
    }
    float uCentre = sum > 0.0 ? weightedT / sum - c.tClosest : 0.5 * (lit.x + lit.y);
    return vec2(sigma * sum / alpha, clamp(uCentre, lo, hi));
}
