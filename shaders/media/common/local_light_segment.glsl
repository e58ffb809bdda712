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
#include "media/common/lamp_quadrature.glsl"

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
