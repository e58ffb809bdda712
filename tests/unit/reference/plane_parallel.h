#pragma once
// Closed forms and deterministic solutions of radiative transfer in a plane-parallel medium with
// isotropic scattering, lit by a collimated beam of irradiance E (on a surface facing it) at
// cosine mu0: what the multiple-scattering judge is checked against.
//   - Chandrasekhar's H-function by iteration of H(μ) = 1 / (1 − (ω/2) μ ∫₀¹ H(μ')/(μ + μ') dμ'),
//     and a semi-infinite medium's reflected radiance E·ω·μ0·H(μ)H(μ0) / (4π(μ + μ0)).
//   - A finite slab of optical depth τ0 by its source function's integral equation
//       S(τ) = ω E/(4π) e^{−τ/μ0} + (ω/2) ∫₀^τ0 E1(|τ − τ'|) S(τ') dτ',
//     S piecewise constant on N cells with the kernel integrated exactly over each pair of cells
//     (exponential integrals E1..E3), solved directly; the reflected and transmitted diffuse
//     radiance are S's exact integrals against e^{−τ/μ} and e^{−(τ0 − τ)/μ}.
#include <cmath>
#include <vector>

namespace nimbus::media::test {

inline constexpr double kPlanePi = 3.14159265358979323846;

// Gauss–Legendre nodes and weights on [0, 1].
inline void gaussLegendre01(int n, std::vector<double>& x, std::vector<double>& w) {
    x.assign(n, 0.0);
    w.assign(n, 0.0);
    for (int i = 0; i < n; ++i) {
        double z = std::cos(kPlanePi * (i + 0.75) / (n + 0.5)), dp = 0.0;
        for (int iteration = 0; iteration < 100; ++iteration) {
            double p0 = 1.0, p1 = 0.0;
            for (int k = 1; k <= n; ++k) {
                const double p2 = p1;
                p1 = p0;
                p0 = ((2.0 * k - 1.0) * z * p1 - (k - 1.0) * p2) / k;
            }
            dp = n * (z * p0 - p1) / (z * z - 1.0);
            const double step = p0 / dp;
            z -= step;
            if (std::abs(step) < 1e-15) break;
        }
        x[i] = 0.5 * (1.0 - z);
        w[i] = 1.0 / ((1.0 - z * z) * dp * dp);
    }
}

// H(μ) for isotropic scattering of albedo ω < 1.
inline double chandrasekharH(double omega, double mu, int nodes = 64) {
    std::vector<double> x, w;
    gaussLegendre01(nodes, x, w);
    std::vector<double> h(nodes, 1.0);
    auto at = [&](double m) {
        double integral = 0.0;
        for (int j = 0; j < nodes; ++j) integral += w[j] * h[j] / (m + x[j]);
        return 1.0 / (1.0 - 0.5 * omega * m * integral);
    };
    for (int iteration = 0; iteration < 5000; ++iteration) {
        double change = 0.0;
        std::vector<double> next(nodes);
        for (int i = 0; i < nodes; ++i) {
            next[i] = at(x[i]);
            change = std::max(change, std::abs(next[i] - h[i]));
        }
        h = next;
        if (change < 1e-14) break;
    }
    return at(mu);
}

inline double semiInfiniteReflected(double E, double omega, double mu0, double mu) {
    return E * omega * mu0 * chandrasekharH(omega, mu) * chandrasekharH(omega, mu0) / (4.0 * kPlanePi * (mu + mu0));
}

inline double expIntegral3(double x) {  // E3, with E1 = −Ei(−x), E2 = e^−x − x E1, E3 = (e^−x − x E2)/2
    if (x <= 0.0) return 0.5;
    const double e1 = -std::expint(-x);
    const double e2 = std::exp(-x) - x * e1;
    return 0.5 * (std::exp(-x) - x * e2);
}

struct SlabRadiance {
    double reflected = 0.0;    // at the lit face, towards the viewer at cosine mu
    double transmitted = 0.0;  // at the far face, diffuse, towards the viewer at cosine mu
};

inline SlabRadiance isotropicSlab(double E, double omega, double tau0, double mu0, double mu, int cells) {
    const int n = cells;
    const double h = tau0 / n;
    std::vector<double> a(static_cast<std::size_t>(n) * n), s(n);
    auto kernel = [&](int i, int j) {  // (1/h) ∫∫ E1(|τ − τ'|) over cells i and j
        if (i == j) return 2.0 / h * (h - 0.5 + expIntegral3(h));
        const double d = (std::abs(i - j) - 1) * h;
        return (expIntegral3(d) - 2.0 * expIntegral3(d + h) + expIntegral3(d + 2.0 * h)) / h;
    };
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) a[i * n + j] = (i == j ? 1.0 : 0.0) - 0.5 * omega * kernel(i, j);
        s[i] = omega * E / (4.0 * kPlanePi) * mu0 * (std::exp(-i * h / mu0) - std::exp(-(i + 1) * h / mu0)) / h;
    }
    for (int k = 0; k < n; ++k)  // Gaussian elimination: the matrix is diagonally dominant
        for (int i = k + 1; i < n; ++i) {
            const double f = a[i * n + k] / a[k * n + k];
            if (f == 0.0) continue;
            for (int j = k; j < n; ++j) a[i * n + j] -= f * a[k * n + j];
            s[i] -= f * s[k];
        }
    for (int i = n - 1; i >= 0; --i) {
        for (int j = i + 1; j < n; ++j) s[i] -= a[i * n + j] * s[j];
        s[i] /= a[i * n + i];
    }
    SlabRadiance out;
    for (int j = 0; j < n; ++j) {
        out.reflected += s[j] * (std::exp(-j * h / mu) - std::exp(-(j + 1) * h / mu));
        out.transmitted += s[j] * (std::exp(-(tau0 - (j + 1) * h) / mu) - std::exp(-(tau0 - j * h) / mu));
    }
    return out;
}

}  // namespace nimbus::media::test
