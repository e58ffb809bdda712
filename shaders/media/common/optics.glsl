// The medium's mathematics in GLSL, mirroring plugins/participating_media/core/optics.h:
// truncated Gaussian kernel ρ(r) = exp(−4.5 r²/R²) (r < R), closed-form optical depth of one
// particle along a ray segment, and the phase functions. Needs common/math.glsl.
const float KERNEL_FALLOFF = 4.5;
const float HALF_SQRT_PI = 0.88622692545275801365;

// erfc(a) = P(a)·exp(−a²) for a ≥ 0, |error| < 1.5e-7 (Abramowitz & Stegun 7.1.26): the polynomial P.
float erfcPolynomial(float a) {
    float t = 1.0 / (1.0 + 0.3275911 * a);
    return ((((1.061405429 * t - 1.453152027) * t + 1.421413741) * t - 0.284496736) * t + 0.254829592) * t;
}

// erf; GLSL has none.
float erfApprox(float x) {
    float a = abs(x);
    float y = 1.0 - erfcPolynomial(a) * exp(-a * a);
    return x < 0.0 ? -y : y;
}

// erf(b) − erf(a) for a ≤ b, from each end's tail g = erfc(|x|) = P(|x|)·exp(−x²), which a caller
// that also needs exp(−x²) has at hand: where both ends lie in one tail, the tails' difference, so
// no 1 − erf cancels.
float erfDifference(float a, float ga, float b, float gb) { return a >= 0.0 ? ga - gb : b <= 0.0 ? gb - ga : 2.0 - ga - gb; }

// A particle of unit radius and unit peak extinction: its optical depth along a ray at impact
// parameter β between μ = lo and hi past the closest point (in radii), within the sphere:
// kernelSegment(β, hi) − kernelSegment(β, lo) (kernel_table.glsl) in closed form, three exp in
// all. Where one table fetch a fragment is most of the work (the slice deposit), this is cheaper
// on llvmpipe than two, and exact where the table is bilinear.
float kernelSpan(float beta, float lo, float hi) {
    const float sk = 2.1213203435596424;  // √KERNEL_FALLOFF
    float h = sqrt(max(1.0 - beta * beta, 0.0));
    float a = sk * clamp(lo, -h, h), b = sk * clamp(hi, -h, h);
    float ga = erfcPolynomial(abs(a)) * exp(-a * a), gb = erfcPolynomial(abs(b)) * exp(-b * b);
    return (HALF_SQRT_PI / sk) * exp(-KERNEL_FALLOFF * beta * beta) * erfDifference(a, ga, b, gb);
}

// φ(α) / (1 − Φ(α)) of the standard normal (the mean of its part beyond α). For α ≥ 0 the
// exp(−α²/2) of φ and of erfc cancel, so it stays exact far into the tail.
float inverseMillsRatio(float alpha) {
    float a = abs(alpha) * 0.70710678;
    if (alpha >= 0.0) return 0.79788456 / erfcPolynomial(a);  // √(2/π) / P
    float gauss = exp(-a * a);
    return 0.79788456 * gauss / (2.0 - erfcPolynomial(a) * gauss);
}

// ∫ exp(−(sk·u)²) du over [lo, hi]. A difference of two erf values cancels when the segment is
// short (a grazing chord, a thin slice), and the float erf's absolute error then dominates; there
// the integrand is smooth enough for 3-point Gauss–Legendre (relative error < 1e-7 for sk·Δ < 0.5).
float gaussianSegment(float sk, float lo, float hi) {
    float width = hi - lo;
    if (sk * width < 0.5) {
        float mid = 0.5 * (lo + hi), half_ = 0.5 * width, node = 0.7745966692 * half_;
        float a = sk * (mid - node), b = sk * mid, c = sk * (mid + node);
        return half_ * (0.5555555556 * exp(-a * a) + 0.8888888889 * exp(-b * b) + 0.5555555556 * exp(-c * c));
    }
    return (HALF_SQRT_PI / sk) * (erfApprox(sk * hi) - erfApprox(sk * lo));
}

// A unit ray against one particle sphere: closest-approach parameter, squared distance, half chord.
struct Chord {
    float tClosest;
    float b2;
    float halfChord;  // 0 when the ray misses
};

Chord chordOf(vec3 origin, vec3 dir, vec3 centre, float radius) {
    vec3 oc = centre - origin;
    float tc = dot(oc, dir);
    vec3 perp = oc - tc * dir;  // not |oc|² − tc²: no cancellation far along the ray
    float b2 = dot(perp, perp);
    float r2 = radius * radius;
    return Chord(tc, b2, b2 < r2 ? sqrt(r2 - b2) : 0.0);
}

// ∫ exp(−k u²) du over [u0, u1] ∩ [−h, h], times exp(−k b²): the optical depth per unit σ.
float chordIntegral(Chord c, float radius, float u0, float u1) {
    float lo = max(u0, -c.halfChord);
    float hi = min(u1, c.halfChord);
    if (c.halfChord <= 0.0 || hi <= lo) return 0.0;
    float k = KERNEL_FALLOFF / (radius * radius);
    float sk = sqrt(k);
    return exp(-k * c.b2) * gaussianSegment(sk, lo, hi);
}

// Optical depth of a particle along the ray segment [t0, t1].
float particleOpticalDepth(Chord c, float radius, float sigma, float t0, float t1) {
    return sigma * chordIntegral(c, radius, t0 - c.tClosest, t1 - c.tClosest);
}

// Density-weighted mean position (as u from the closest point) of the kernel on [u0, u1]; the
// in-scattering of a particle is evaluated there. Falls back to the middle for a vanishing integral.
float chordCentroid(Chord c, float radius, float u0, float u1) {
    float lo = max(u0, -c.halfChord);
    float hi = min(u1, c.halfChord);
    if (hi <= lo) return 0.5 * (lo + hi);
    float k = KERNEL_FALLOFF / (radius * radius);
    float sk = sqrt(k);
    float mass = gaussianSegment(sk, lo, hi);
    if (mass < 1e-12 * (hi - lo)) return 0.5 * (lo + hi);
    // ∫ u exp(−k u²) du = −exp(−k u²) / (2k)
    return clamp((exp(-k * lo * lo) - exp(-k * hi * hi)) / (2.0 * k * mass), lo, hi);
}

// Inverse of erf on (−1, 1), single-precision polynomial fit (M. Giles, "Approximating the erfinv
// function", GPU Computing Gems, 2010); |relative error| < 4e-7 away from ±1.
float erfInverse(float x) {
    x = clamp(x, -0.9999999, 0.9999999);
    float w = -log((1.0 - x) * (1.0 + x));
    float p;
    if (w < 5.0) {
        w -= 2.5;
        p = 2.81022636e-08;
        p = 3.43273939e-07 + p * w;
        p = -3.5233877e-06 + p * w;
        p = -4.39150654e-06 + p * w;
        p = 0.00021858087 + p * w;
        p = -0.00125372503 + p * w;
        p = -0.00417768164 + p * w;
        p = 0.246640727 + p * w;
        p = 1.50140941 + p * w;
    } else {
        w = sqrt(w) - 3.0;
        p = -0.000200214257;
        p = 0.000100950558 + p * w;
        p = 0.00134934322 + p * w;
        p = -0.00367342844 + p * w;
        p = 0.00573950773 + p * w;
        p = -0.0076224613 + p * w;
        p = 0.00943887047 + p * w;
        p = 1.00167406 + p * w;
        p = 2.83297682 + p * w;
    }
    return p * x;
}

// Where along [u0, u1] a particle's in-scattering is best evaluated when it is composited as one
// layer. Its exact contribution is ∫₀^τ J(v) e^−v dv with v the optical depth from where the ray
// enters it; for J linear in v that equals J(v̄)(1 − e^−τ) at v̄ = (1 − (1+τ)e^−τ)/(1 − e^−τ), the
// e^−v-weighted mean (τ/2 for a thin particle, → 1 for a thick one: its front is what is seen).
// v̄/τ: the share of the layer's optical depth in front of that point.
float shadingDepthFraction(float tau) {
    return tau < 1e-3 ? 0.5 - tau / 12.0 : (1.0 - (1.0 + tau) * exp(-tau)) / (tau * oneMinusExpNeg(tau));
}

// Returns the u at which the kernel's cumulative optical depth from u0 reaches v̄.
float chordShadingPoint(Chord c, float radius, float u0, float u1, float tau) {
    float lo = max(u0, -c.halfChord);
    float hi = min(u1, c.halfChord);
    if (hi <= lo) return 0.5 * (lo + hi);
    float fraction = shadingDepthFraction(tau);
    float sk = sqrt(KERNEL_FALLOFF) / radius;
    float a = erfApprox(sk * lo), b = erfApprox(sk * hi);
    return clamp(erfInverse(a + fraction * (b - a)) / sk, lo, hi);
}

// Mean and variance (along the ray, as u from the closest point) of the kernel restricted to
// [u0, u1]: a Gaussian of deviation s = R/3 truncated there.
vec2 chordMoments(Chord c, float radius, float u0, float u1) {
    float lo = max(u0, -c.halfChord), hi = min(u1, c.halfChord);
    float s = radius / 3.0;
    if (hi <= lo) return vec2(0.5 * (lo + hi), 0.0);
    float a = lo / s, b = hi / s;
    float pa = exp(-0.5 * a * a), pb = exp(-0.5 * b * b);  // φ up to 1/√(2π), which cancels
    float z = 1.2533141373 * (erfApprox(b * 0.70710678) - erfApprox(a * 0.70710678));  // √(π/2)·(erf…)
    if (z < 1e-7) return vec2(0.5 * (lo + hi), (hi - lo) * (hi - lo) / 12.0);
    float m = (pa - pb) / z;
    float v = 1.0 + (a * pa - b * pb) / z - m * m;
    return vec2(s * m, s * s * max(v, 0.0));
}

// Henyey–Greenstein between unit vectors a, b (cos θ = a·b). Its denominator 1 + g² − 2g cos θ is
// (1 − g)² + g|a − b|² = (1 + g)² − g|a + b|²: near the peak of g = 0.99 it is ~1e-4, and forming it
// from a float cos θ would lose ~1% to cancellation (rings around the sun in a forward-scattering
// medium); the chord lengths |a ∓ b| keep full precision.
float henyeyGreenstein(vec3 a, vec3 b, float g) {
    vec3 chord = g >= 0.0 ? a - b : a + b;
    float denom = max((1.0 - abs(g)) * (1.0 - abs(g)) + abs(g) * dot(chord, chord), 1e-8);
    return (1.0 - g * g) / (4.0 * PI * denom * sqrt(denom));
}

float rayleighPhase(float cosTheta) { return 3.0 / (16.0 * PI) * (1.0 + cosTheta * cosTheta); }

float phaseValue(float phase, float g, vec3 a, vec3 b) {
    return phase > 0.5 ? rayleighPhase(dot(a, b)) : henyeyGreenstein(a, b, g);
}
