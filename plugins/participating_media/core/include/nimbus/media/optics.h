#pragma once
// The medium's mathematics (docs/design.md §2), in one place: the truncated Gaussian kernel, the closed-form
// optical depth of one particle along a ray segment, transmittance, and the phase functions. The
// reference renderer calls these; the GLSL in shaders/ mirrors them line for line.
//
// Does not: know about scenes, lights or meshes; allocate; use float where precision matters (all double).
#include <cmath>
#include <limits>

#include <glm/glm.hpp>

#include "nimbus/media/particle_set.h"

namespace nimbus::media {

// ρ(r) = exp(-kKernelFalloff · r²/R²) for r < R, else 0: a Gaussian with s = R/3, truncated at R.
inline constexpr double kKernelFalloff = 4.5;
inline constexpr double kPi = 3.14159265358979323846;

// Kernel value at squared distance r2 from the centre of a particle of radius R.
inline double kernelDensity(double r2, double radius) {
    const double R2 = radius * radius;
    return r2 < R2 ? std::exp(-kKernelFalloff * r2 / R2) : 0.0;
}

// Where a unit ray meets a particle's sphere. The ray point is origin + t·dir; tClosest is the
// parameter of the point nearest the centre, b2 the squared ray–centre distance, halfChord
// sqrt(R² - b²) (0 when the ray misses: b2 >= R²).
struct ChordGeometry {
    double tClosest = 0.0;
    double b2 = 0.0;
    double halfChord = 0.0;
    bool hit() const { return halfChord > 0.0; }
    double tEnter() const { return tClosest - halfChord; }
    double tExit() const { return tClosest + halfChord; }
};

// `dir` must be unit length. b² is computed from the perpendicular vector (not |v|² - t²) so it does
// not cancel when the centre is far along the ray.
ChordGeometry chordGeometry(const glm::dvec3& origin, const glm::dvec3& dir, const glm::dvec3& centre, double radius);

// ∫_{a0}^{a1} exp(-x²) dx for any a0 <= a1, accurate to a few ulps relative even when the interval
// is tiny (where erf(a1) - erf(a0) would cancel) or both ends are on the same side far out (erfc).
double gaussianIntegral(double a0, double a1);

// Optical depth of one particle (peak extinction sigma, radius R) along the ray segment whose ends are
// u0 <= u1, measured along the ray from the point closest to the centre, at squared ray–centre distance
// b2. The segment is clipped to the chord |u| <= sqrt(R² - b²):
//   τ = σ · exp(-k b²) · ∫ exp(-k u²) du = σ · exp(-k b²) · [gaussianIntegral(√k u0, √k u1)] / √k,  k = 4.5/R².
// Zero when the ray misses or the segment is outside the chord. Exact (closed form) for any σ >= 0.
double particleOpticalDepth(double sigma, double radius, double b2, double u0, double u1);

// The same with the chord already known (halfChord = sqrt(R² - b²)); the hot loops use this one.
double particleOpticalDepthOnChord(double sigma, double radius, double b2, double halfChord, double u0, double u1);

// Optical depth of a particle along the ray segment [t0, t1] (a convenience over chordGeometry).
double particleOpticalDepth(const ChordGeometry& chord, double sigma, double radius, double t0, double t1);

// T = exp(-τ); underflows cleanly to 0 for huge τ, 1 for τ <= 0 (never NaN for τ >= 0 or +inf).
inline double transmittance(double tau) { return tau <= 0.0 ? 1.0 : std::exp(-tau); }

// 1 - exp(-τ) without cancellation for small τ.
inline double opacity(double tau) { return tau <= 0.0 ? 0.0 : -std::expm1(-tau); }

// Phase functions, normalised over the sphere (∫ p dω = 1). cosTheta is the cosine between the
// direction light travels before and after scattering: 1 = straight on (forward).
inline double henyeyGreenstein(double cosTheta, double g) {
    const double denom = 1.0 + g * g - 2.0 * g * cosTheta;
    return (1.0 - g * g) / (4.0 * kPi * denom * std::sqrt(denom));
}

inline double rayleigh(double cosTheta) { return 3.0 / (16.0 * kPi) * (1.0 + cosTheta * cosTheta); }

inline double phaseValue(PhaseFunction phase, double g, double cosTheta) {
    return phase == PhaseFunction::Rayleigh ? rayleigh(cosTheta) : henyeyGreenstein(cosTheta, g);
}

}  // namespace nimbus::media
