// Tests engine/assets/src/surface_brdf.cpp against values of the glTF BRDF worked out by hand, and
// against what a BRDF must do: reciprocity, no energy gain for white, metals without diffuse.
#include "nimbus/assets/surface_brdf.h"

#include <gtest/gtest.h>

#include <cmath>

namespace nimbus::assets {
namespace {

constexpr double kPi = 3.14159265358979323846;
const glm::dvec3 kUp(0.0, 1.0, 0.0);

glm::dvec3 direction(double theta, double phi) {
    return {std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)};
}

TEST(SurfaceBrdf, RoughDielectricHeadOn) {
    // n = v = l: F = 0.04, D = 1/π (α = 1), Vis = 1/4: f = 0.96 c/π + 0.04/(4π).
    const glm::dvec3 c(0.8, 0.5, 0.2);
    const glm::dvec3 f = brdfTimesCosine(surfaceBrdf(c, 0.0, 1.0), kUp, kUp, kUp, 1.0);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(f[i], (0.96 * c[i] + 0.01) / kPi, 1e-15);
}

TEST(SurfaceBrdf, MetalHasNoDiffuseAndItsBaseColourIsF0) {
    // Head-on with α² = r⁴: D = 1/(π α²), Vis = 1/(4 α²)... = 1/((1 + 1)(1 + 1)) at n·l = n·v = 1.
    const double r = 0.5, a2 = std::pow(r, 4);
    const glm::dvec3 c(0.9, 0.6, 0.3);
    const glm::dvec3 f = brdfTimesCosine(surfaceBrdf(c, 1.0, r), kUp, kUp, kUp, 1.0);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(f[i], c[i] * (1.0 / (kPi * a2)) * 0.25, 1e-12);
}

TEST(SurfaceBrdf, ReciprocalAndFiniteAtGrazingAngles) {
    const SurfaceBrdf brdf = surfaceBrdf(glm::dvec3(0.7), 0.3, 0.4);
    const glm::dvec3 a = direction(0.3, 0.2), b = direction(1.1, 2.5);
    const glm::dvec3 fab = brdfTimesCosine(brdf, kUp, a, b, b.y) / b.y;
    const glm::dvec3 fba = brdfTimesCosine(brdf, kUp, b, a, a.y) / a.y;
    EXPECT_NEAR(fab.x, fba.x, 1e-12 * fab.x);
    // l = −v (h = 0) and a view in the plane (n·v = 0): finite, no NaN.
    const glm::dvec3 flat(1.0, 0.0, 0.0);
    EXPECT_TRUE(std::isfinite(brdfTimesCosine(brdf, kUp, flat, direction(0.5, 0.0), 0.5 * 0.0 + std::cos(0.5)).x));
    const glm::dvec3 l = direction(0.2, 0.0);
    EXPECT_TRUE(std::isfinite(brdfTimesCosine(brdf, kUp, -l, l, l.y).x));
}

TEST(SurfaceBrdf, WhiteReflectsAtMostWhatArrives) {
    // Directional albedo ∫ f cos dω over the hemisphere (midpoint rule) stays ≤ 1 for white, and
    // is near 1 for a dielectric (the diffuse part dominates). A rough metal loses what its
    // microfacets would scatter more than once (single-scattering GGX: 0.34 at roughness 1).
    for (const double roughness : {0.2, 0.5, 1.0}) {
        for (const double metallic : {0.0, 1.0}) {
            const SurfaceBrdf brdf = surfaceBrdf(glm::dvec3(1.0), metallic, roughness);
            const glm::dvec3 v = direction(0.6, 0.0);
            const int n = 400;
            double albedo = 0.0;
            for (int i = 0; i < n; ++i)
                for (int j = 0; j < 2 * n; ++j) {
                    const double theta = (i + 0.5) * (kPi / 2) / n, phi = (j + 0.5) * kPi / n;
                    const glm::dvec3 l = direction(theta, phi);
                    albedo += brdfTimesCosine(brdf, kUp, v, l, l.y).x * std::sin(theta) * (kPi / 2 / n) * (kPi / n);
                }
            EXPECT_LE(albedo, 1.0 + 1e-3) << "roughness " << roughness << " metallic " << metallic;
            EXPECT_GT(albedo, metallic > 0.0 ? 0.3 : 0.9) << "roughness " << roughness << " metallic " << metallic;
        }
    }
}

}  // namespace
}  // namespace nimbus::assets
