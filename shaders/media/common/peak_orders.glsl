// The phase that multiplies a light's E·V·e^−τ at a point of the medium (docs/design.md §3). In the
// multiple model it also carries the light that the forward peak scattered on its way in, which the
// diffusion grid cannot: δ-Eddington (Joseph, Wiscombe and Weinman), as the grid uses it, counts the
// share f = g² of each scattering that stays in the peak as unscattered, so the light arrives as
//     E e^{−(1 − fω)τ} = E e^{−τ} Σₙ (fωτ)ⁿ / n!,
// the n-th term scattered n times within the peak. The grid takes all of it as its diffuse source,
// but that light still travels near the light's direction: seen against the light (a cloud's silver
// lining) it is the brightest there is. Each term is seen through the whole phase of n + 1 lobes,
// p(θ, gⁿ⁺¹) (lobes compose by multiplying their mean cosines), for n = 1..3: past g⁴ ≈ 0.5 the
// light is as diffuse as the grid's. The grid also holds the off-peak part of these orders, spread
// over every direction; weighting them by f alone to avoid that erred more (design-notes.md: the
// forward peak's orders). Needs common/math.glsl and media/common/optics.glsl.

const int PEAK_ORDERS = 3;

// p(θ) + Σ_{n=1..3} (fωτ)ⁿ/n! p(θ, gⁿ⁺¹) for light with transmittance e^−τ to it (the splats' fit
// holds the mesh visibility in it too, which only lowers the orders in a mesh's shadow), albedo ω
// (its luminance, as the grid takes it); just p(θ) in the single model, for Rayleigh, or for g ≤ 0.
float litPhase(float phaseKind, float g, float albedo, float transmittance, vec3 toLight, vec3 viewDir) {
    float phase = phaseValue(phaseKind, g, toLight, viewDir);
#ifdef MEDIA_MULTIPLE
    if (phaseKind > 0.5 || !(g > 0.0) || !(transmittance > 0.0)) return phase;
    float x = g * g * albedo * -log(min(transmittance, 1.0));
    float weight = 1.0, gn = g;
    for (int n = 1; n <= PEAK_ORDERS; ++n) {
        weight *= x / float(n);
        gn *= g;
        phase += weight * henyeyGreenstein(toLight, viewDir, gn);
    }
#endif
    return phase;
}
