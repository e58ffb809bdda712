// The multiple-scattering judge (reference/src/scattering_paths.cpp) against what is known without
// it: Chandrasekhar's semi-infinite medium, finite slabs by their integral equation
// (plane_parallel.h), the white furnace, and order 1 against the single-scattering model. A Monte
// Carlo figure is compared within its own standard error: the mean over a patch of pixels (each its
// own stream of paths) with the standard error of that mean, sqrt(Σ SE²)/n.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>

#include "plane_parallel.h"
#include "reference_fixture.h"

namespace nimbus::media::test {
namespace {

using reference::ReferenceRenderer;

reference::ReferenceSettings multiple(int w, int h, int spp) {
    reference::ReferenceSettings s = settings(w, h);
    s.scattering = assets::Scattering::Multiple;
    s.spp = spp;
    return s;
}

struct PatchMean {
    double mean = 0.0, standardError = 0.0;  // red channel (the tests' media are grey)
};

// Each case its own seed, so their errors are independent.
PatchMean patchMean(const TestScene& s, int w, int h, int spp, std::uint64_t seed = 1) {
    TestScene copy = s;
    reference::ReferenceSettings settings = multiple(w, h, spp);
    settings.seed = seed;
    const ReferenceRenderer renderer(copy.inputs(), settings);
    assets::RgbImage error;
    const assets::RgbImage image = renderer.render(nullptr, &error);
    PatchMean out;
    double variance = 0.0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            out.mean += image.at(x, y).x;
            variance += double(error.at(x, y).x) * error.at(x, y).x;
        }
    const double n = static_cast<double>(w) * h;
    out.mean /= n;
    out.standardError = std::sqrt(variance) / n;
    return out;
}

Medium isotropic(float albedo) { return medium(albedo, 0.0f); }

// A plane-parallel medium of optical depth `tau` between y = −thickness/2 and +thickness/2, `width`
// wide, lit by a sun of 1 lux travelling −y, seen by a small orthographic camera along `view`.
TestScene planeParallel(float albedo, double tau, double thickness, double width, const glm::dvec3& view, const glm::dvec3& aim) {
    TestScene s;
    Medium m = isotropic(albedo);
    m.extinction = static_cast<float>(tau / thickness);
    s.volumes = {makeVolume(VolumeShape::Box, glm::dmat4(1.0), {width, thickness, width}, m)};
    s.lights = {fixtures::sun({0.0, -1.0, 0.0}, 1.0f)};
    s.camera = fixtures::orthographic(aim - 5.0 * view, aim, 0.05, 0.05, glm::abs(view.y) > 0.99 ? glm::dvec3(0, 0, -1) : glm::dvec3(0, 1, 0));
    return s;
}

glm::dvec3 viewAt(double mu, double sign) { return glm::normalize(glm::dvec3(std::sqrt(1.0 - mu * mu), sign * mu, 0.0)); }

void expectWithin(const PatchMean& m, double expected, double relative, const char* what) {
    std::printf("[ measured ] %s: judge %.6g ± %.2g (%.3f%%), expected %.6g, off by %.3f%%\n", what, m.mean, m.standardError,
                100.0 * m.standardError / expected, expected, 100.0 * (m.mean - expected) / expected);
    EXPECT_LE(std::abs(m.mean - expected), relative * expected) << what;
    EXPECT_LE(std::abs(m.mean - expected), 3.0 * m.standardError + 1e-9 * expected) << what << ": beyond 3 standard errors";
    EXPECT_LT(3.0 * m.standardError, relative * expected) << what << ": too few paths to tell";
}

// τ = 2000 across, seen along the sun (μ = μ0 = 1) and at μ = 0.5: E ω μ0 H(μ)H(μ0)/(4π(μ + μ0)).
TEST(ReferenceMultiple, SemiInfiniteMediumMatchesChandrasekhar) {
    for (const float albedo : {0.9f, 0.99f}) {
        for (const double mu : {1.0, 0.5}) {
            const glm::dvec3 view = viewAt(mu, -1.0);
            const TestScene s = planeParallel(albedo, 2000.0, 2000.0, 2000.0, view, {0.0, 1000.0, 0.0});
            const PatchMean m = patchMean(s, 4, 4, 4000, static_cast<std::uint64_t>(1000 * albedo + 10 * mu));
            char what[96];
            std::snprintf(what, sizeof what, "semi-infinite, albedo %.2f, mu %.1f", albedo, mu);
            expectWithin(m, semiInfiniteReflected(1.0, albedo, 1.0, mu), 0.01, what);
        }
    }
}

TEST(PlaneParallel, TheSlabSolverConvergesAndMeetsTheHFunction) {
    // Deep enough, the slab is the semi-infinite medium.
    const double deep = isotropicSlab(1.0, 0.9, 40.0, 1.0, 1.0, 2000).reflected;
    EXPECT_NEAR(deep, semiInfiniteReflected(1.0, 0.9, 1.0, 1.0), 1e-3 * deep);
    const SlabRadiance coarse = isotropicSlab(1.0, 0.9, 4.0, 1.0, 0.5, 500), fine = isotropicSlab(1.0, 0.9, 4.0, 1.0, 0.5, 1000);
    EXPECT_NEAR(coarse.reflected, fine.reflected, 5e-4 * fine.reflected);
    EXPECT_NEAR(coarse.transmitted, fine.transmitted, 5e-4 * fine.transmitted);
    // H(1) for ω = 0.9 is 3.4^(1/2)-ish: the multiple/single ratio along the sun is H(1)².
    EXPECT_NEAR(std::pow(chandrasekharH(0.9, 1.0), 2.0), 3.4, 0.1);
}

// Optical depth 1 and 4, albedo 0.9: the reflected and the diffusely transmitted radiance at
// normal viewing and at μ = 0.5, for normal incidence.
TEST(ReferenceMultiple, SlabsMatchTheirIntegralEquation) {
    for (const double tau : {1.0, 4.0}) {
        for (const double mu : {1.0, 0.5}) {
            const SlabRadiance exact = isotropicSlab(1.0, 0.9, tau, 1.0, mu, 1000);
            const TestScene top = planeParallel(0.9f, tau, 1.0, 400.0, viewAt(mu, -1.0), {0.0, 0.5, 0.0});
            const TestScene bottom = planeParallel(0.9f, tau, 1.0, 400.0, viewAt(mu, 1.0), {0.0, -0.5, 0.0});
            char what[96];
            std::snprintf(what, sizeof what, "slab tau %.0f reflected, mu %.1f", tau, mu);
            const auto seed = static_cast<std::uint64_t>(100 * tau + 10 * mu);
            expectWithin(patchMean(top, 4, 4, 4000, seed), exact.reflected, 0.01, what);
            std::snprintf(what, sizeof what, "slab tau %.0f transmitted, mu %.1f", tau, mu);
            // The thick slab's transmitted light is faint and its paths long: more of them.
            expectWithin(patchMean(bottom, 4, 4, tau > 2.0 ? 16000 : 4000, seed + 1), exact.transmitted, 0.01, what);
        }
    }
}

// Albedo 1, no lights, background = ambient = L: every pixel is L. A cloud of thin and dense
// particles and a volume; 99% of the pixels within 3 of their standard errors (what 3σ promises),
// every one within 5, and the image's mean within 3 of its own.
TEST(ReferenceMultiple, WhiteFurnaceEveryPixelIsTheEnvironment) {
    TestScene s;
    const float L = 0.7f;
    s.builder.scene.environment.background = glm::vec3(L);
    s.builder.scene.environment.ambient = glm::vec3(L);
    addRandomCloud(s.particles, 60, 17, {-2, -1, -2}, {2, 1, 2}, 0.3f, 1.2f, 3.0f, medium(1.0f, 0.6f));
    addRandomCloud(s.particles, 20, 5, {-2, -1, -2}, {2, 1, 2}, 0.2f, 0.5f, 40.0f, medium(1.0f, -0.3f, glm::vec3(0.0f), PhaseFunction::Rayleigh));
    Medium box = medium(1.0f, 0.8f);
    box.extinction = 2.0f;
    s.volumes = {makeVolume(VolumeShape::Ellipsoid, glm::translate(glm::dmat4(1.0), glm::dvec3(1.0, 0.5, 0.0)), {2.0, 1.0, 1.5}, box)};
    s.camera = fixtures::lookAt({0.0, 1.0, 8.0}, {0.0, 0.0, 0.0});
    const int w = 24, h = 16;
    const ReferenceRenderer renderer(s.inputs(), multiple(w, h, 256));
    assets::RgbImage error;
    const assets::RgbImage image = renderer.render(nullptr, &error);
    int within3 = 0, within5 = 0;
    double sum = 0.0, variance = 0.0, worst = 0.0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const double d = std::abs(image.at(x, y).x - L), se = error.at(x, y).x;
            within3 += d <= 3.0 * se + 1e-6 ? 1 : 0;
            within5 += d <= 5.0 * se + 1e-6 ? 1 : 0;
            worst = std::max(worst, se > 0.0 ? d / se : 0.0);
            sum += image.at(x, y).x;
            variance += se * se;
        }
    const int n = w * h;
    std::printf("[ measured ] white furnace: %d of %d pixels within 3 SE, worst %.2f SE, mean %.5f ± %.2g\n", within3, n, worst,
                sum / n, std::sqrt(variance) / n);
    EXPECT_GE(within3, static_cast<int>(0.99 * n));
    EXPECT_EQ(within5, n);
    EXPECT_LE(std::abs(sum / n - L), 3.0 * std::sqrt(variance) / n + 1e-6);
}

// With ambient 0 the multiple model's exact part (its order 1) is the single model, to 1e-6.
TEST(ReferenceMultiple, OrderOneAloneIsTheSingleModel) {
    TestScene s;
    s.lights = {fixtures::sun({0.3, -1.0, -0.2}, 2.0f), fixtures::sun({-1.0, -0.2, 0.1}, 0.5f)};
    addRandomCloud(s.particles, 40, 3, {-2, -1, -2}, {2, 1, 2}, 0.3f, 1.0f, 4.0f, medium(0.8f, 0.5f, glm::vec3(0.1f)));
    const auto in = s.inputs();
    reference::ReferenceSettings one = multiple(16, 12, 4);
    const ReferenceRenderer multipleRenderer(in, one);
    one.scattering = assets::Scattering::Single;
    const ReferenceRenderer singleRenderer(in, one);
    for (int y = 0; y < 12; ++y)
        for (int x = 0; x < 16; ++x) {
            const auto m = multipleRenderer.tracePixel(x, y), single = singleRenderer.tracePixel(x, y);
            const glm::dvec3 orderOne = m.radiance - m.paths;
            for (int c = 0; c < 3; ++c) ASSERT_NEAR(orderOne[c], single.radiance[c], 1e-6 * std::max(1.0, single.radiance[c])) << x << "," << y;
        }
}

// Albedo 1 at τ = 10⁴: every path ends (Russian roulette), and the pixel is finite.
TEST(ReferenceMultiple, AlbedoOneAtOpticalDepthTenThousandEnds) {
    TestScene s = planeParallel(1.0f, 1e4, 10.0, 100.0, viewAt(1.0, -1.0), {0.0, 5.0, 0.0});
    const auto start = std::chrono::steady_clock::now();
    const PatchMean m = patchMean(s, 2, 2, 200);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("[ measured ] albedo 1, tau 1e4: %.4g ± %.2g in %.2f s for 800 paths\n", m.mean, m.standardError, seconds);
    EXPECT_TRUE(std::isfinite(m.mean));
    EXPECT_TRUE(std::isfinite(m.standardError));
    EXPECT_GT(m.mean, 0.0);
}

}  // namespace
}  // namespace nimbus::media::test
