#include "nimbus/media/optics.h"

#include <algorithm>
#include <cmath>

namespace nimbus::media {
namespace {

constexpr double kHalfSqrtPi = 0.88622692545275801365;  // √π / 2

// 6-point Gauss–Legendre on [-1, 1]: exact to degree 11. On intervals short relative to the scale
// of exp(-x²) this is accurate to double precision, where erf(a1) - erf(a0) would lose digits.
constexpr double kNodes[3] = {0.2386191860831969086, 0.6612093864662645136, 0.9324695142031520278};
constexpr double kWeights[3] = {0.4679139345726910473, 0.3607615730481386076, 0.1713244923791703450};

double gaussLegendreGaussian(double a0, double width) {
    const double half = 0.5 * width;
    const double mid = a0 + half;
    double sum = 0.0;
    for (int i = 0; i < 3; ++i) {
        const double xp = mid + half * kNodes[i];
        const double xm = mid - half * kNodes[i];
        sum += kWeights[i] * (std::exp(-xp * xp) + std::exp(-xm * xm));
    }
    return sum * half;
}

// ∫ exp(-x²) over [a0, a0 + width]; the width is passed on its own so that a short interval keeps the
// relative precision of its length (a1 - a0 after scaling would not).
double gaussianIntegralWidth(double a0, double width) {
    if (!(width > 0.0)) return 0.0;
    const double a1 = a0 + width;
    const double reach = std::max(std::abs(a0), std::abs(a1));
    // Short intervals (relative to how fast exp(-x²) varies there): quadrature, no cancellation.
    if (width * (1.0 + reach) <= 0.25) return gaussLegendreGaussian(a0, width);
    // Same side of zero: subtract the small erfc tails instead of erf values close to ±1.
    if (a0 >= 0.0) return kHalfSqrtPi * (std::erfc(a0) - std::erfc(a1));
    if (a1 <= 0.0) return kHalfSqrtPi * (std::erfc(-a1) - std::erfc(-a0));
    return kHalfSqrtPi * (std::erf(a1) - std::erf(a0));  // opposite signs: a sum of two positives
}

// sqrt(R² - b²), 0 outside. fma rounds R·R - b² once, so a grazing chord (b → R) keeps the relative
// precision its input allows instead of losing it to the rounding of R².
double halfChordLength(double radius, double b2) {
    const double h2 = std::fma(radius, radius, -b2);
    return h2 > 0.0 ? std::sqrt(h2) : 0.0;
}

}  // namespace

ChordGeometry chordGeometry(const glm::dvec3& origin, const glm::dvec3& dir, const glm::dvec3& centre, double radius) {
    ChordGeometry c;
    const glm::dvec3 v = centre - origin;
    c.tClosest = glm::dot(v, dir);
    const glm::dvec3 perpendicular = v - c.tClosest * dir;
    c.b2 = glm::dot(perpendicular, perpendicular);
    c.halfChord = halfChordLength(radius, c.b2);
    return c;
}

double gaussianIntegral(double a0, double a1) { return a1 > a0 ? gaussianIntegralWidth(a0, a1 - a0) : 0.0; }

double particleOpticalDepthOnChord(double sigma, double radius, double b2, double halfChord, double u0, double u1) {
    if (!(sigma > 0.0) || !(halfChord > 0.0)) return 0.0;
    const double sqrtK = std::sqrt(kKernelFalloff) / radius;
    const double peak = sigma * std::exp(-kKernelFalloff * b2 / (radius * radius)) / sqrtK;
    if (u0 <= -halfChord && u1 >= halfChord)  // the whole chord (the common case for light rays): one erf
        return peak * 2.0 * kHalfSqrtPi * std::erf(sqrtK * halfChord);
    u0 = std::max(u0, -halfChord);
    u1 = std::min(u1, halfChord);
    if (!(u1 > u0)) return 0.0;
    return peak * gaussianIntegralWidth(sqrtK * u0, sqrtK * (u1 - u0));
}

double particleOpticalDepth(double sigma, double radius, double b2, double u0, double u1) {
    const double h = halfChordLength(radius, b2);
    return h > 0.0 ? particleOpticalDepthOnChord(sigma, radius, b2, h, u0, u1) : 0.0;
}

double particleOpticalDepth(const ChordGeometry& chord, double sigma, double radius, double t0, double t1) {
    if (!chord.hit()) return 0.0;
    return particleOpticalDepthOnChord(sigma, radius, chord.b2, chord.halfChord, t0 - chord.tClosest,
                                       t1 - chord.tClosest);
}

}  // namespace nimbus::media
