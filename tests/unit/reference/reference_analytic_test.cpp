// Tests plugins/participating_media/reference/src/reference_renderer.cpp against closed forms and
// brute-force quadrature: the cases where the right answer is known independently.
#include <gtest/gtest.h>

#include <cstdio>

#include "nimbus/assets/light_model.h"
#include "reference_fixture.h"

namespace nimbus::media::test {
namespace {

using reference::ReferenceRenderer;

// A few overlapping particles of different sizes and densities around the origin.
void addBlob(ParticleSet& set, const Medium& m) {
    set.push({0.0, 0.0, 0.0}, 1.5f, 0.8f, m);
    set.push({0.9, 0.3, -0.4}, 1.0f, 2.5f, m);
    set.push({-0.7, -0.5, 0.6}, 0.6f, 6.0f, m);
    set.push({0.2, 1.1, 0.1}, 0.4f, 40.0f, m);  // small and optically thick
    set.push({-1.8, 0.9, -2.0}, 2.0f, 0.05f, m);
}

double relative(double value, long double reference) {
    return static_cast<double>(std::abs((value - reference) / reference));
}

TEST(ReferenceAnalytic, AbsorberBeforeWhiteBackgroundIsExactlyExpMinusTau) {
    TestScene s;
    s.builder.scene.environment.background = glm::vec3(1.0f);
    s.builder.scene.environment.ambient = glm::vec3(0.7f);  // albedo 0: must not matter
    s.lights = {fixtures::sun({0.3, -1.0, -0.2}, 5.0f)};
    addBlob(s.particles, medium(0.0f));
    s.camera = fixtures::lookAt({0.5, 0.3, 6.0}, {0.0, 0.2, 0.0}, 0.9);
    const int w = 40, h = 30;
    const auto in = s.inputs();
    const ReferenceRenderer renderer(in, settings(w, h));
    const assets::RgbImage image = renderer.render();
    const reference::CameraFrame frame = reference::makeCameraFrame(s.camera, w, h);
    double worst = 0.0;
    int covered = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const reference::CameraRay ray = reference::cameraRay(frame, x, y);
            const long double tau = numericOpticalDepth(s.particles, ray.origin, ray.direction, 1e30);
            const long double expected = std::exp(-tau);
            covered += tau > 1e-3L ? 1 : 0;
            for (int c = 0; c < 3; ++c) {
                const double e = relative(image.at(x, y)[c], expected);
                worst = std::max(worst, e);
                ASSERT_LT(e, 1e-6) << x << "," << y;
            }
        }
    std::printf("absorber: worst relative error vs exp(-tau by quadrature): %.3g over %d covered pixels\n", worst, covered);
    EXPECT_GT(covered, w * h / 4);
}

TEST(ReferenceAnalytic, EmissionAndAmbientScatterTimesOpacity) {
    // With S̄ constant along the ray, L = S (1 - T) + T·background exactly.
    TestScene s;
    const glm::vec3 background(0.1f, 0.2f, 0.3f), ambient(0.5f, 0.25f, 1.0f), emission(0.3f, 0.6f, 0.9f);
    s.builder.scene.environment.background = background;
    s.builder.scene.environment.ambient = ambient;
    const float albedo = 0.6f;
    addBlob(s.particles, medium(albedo, 0.5f, emission));
    s.camera = fixtures::lookAt({-0.4, 0.2, 7.0}, {0.0, 0.2, 0.0}, 0.8);
    const int w = 32, h = 24;
    const auto in = s.inputs();
    const ReferenceRenderer renderer(in, settings(w, h));
    const reference::CameraFrame frame = reference::makeCameraFrame(s.camera, w, h);
    double worst = 0.0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const reference::CameraRay ray = reference::cameraRay(frame, x, y);
            const long double T = std::exp(-numericOpticalDepth(s.particles, ray.origin, ray.direction, 1e30));
            const reference::RayRadiance r = renderer.tracePixel(x, y);
            for (int c = 0; c < 3; ++c) {
                const long double source = static_cast<long double>(albedo) * ambient[c] + emission[c];
                const long double expected = source * (1.0L - T) + T * static_cast<long double>(background[c]);
                const double e = relative(r.radiance[c], expected);
                worst = std::max(worst, e);
                ASSERT_LT(e, 1e-9) << x << "," << y;
            }
        }
    std::printf("emission + ambient: worst relative error vs S(1-T) + T·background: %.3g\n", worst);
}

TEST(ReferenceAnalytic, AlbedoZeroMeansNoInScattering) {
    // Lights, ambient, a lit ground and a box: with albedo 0 the medium only attenuates (and shadows):
    // no in-scattered light at all, every pixel is T(0,d)·L_s, and L_s equals the surface without the
    // medium wherever the medium does not shadow it.
    TestScene s;
    const int ground = s.builder.addMaterial({0.6f, 0.5f, 0.4f});
    s.builder.addMesh({fixtures::quad({-20, -2, 20}, {40, 0, 0}, {0, 0, -40}, ground), fixtures::box({1.5, -2, -1}, {2.5, 0, 0})});
    s.builder.scene.environment.background = glm::vec3(0.2f, 0.3f, 0.5f);
    s.builder.scene.environment.ambient = glm::vec3(0.1f);
    s.lights = {fixtures::sun({0.4, -1.0, -0.3}, 3.0f)};
    addBlob(s.particles, medium(0.0f));
    s.camera = fixtures::lookAt({1.0, 2.0, 7.0}, {0.0, -0.5, 0.0}, 0.9);
    const int w = 40, h = 30;
    const auto with = s.inputs();
    ParticleSet none;
    auto without = with;
    without.particles = &none;
    const ReferenceRenderer a(with, settings(w, h)), b(without, settings(w, h));
    const glm::dvec3 toSun = -s.lights[0].direction;
    double worst = 0.0;
    int unshadowed = 0, shadowed = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const reference::RayRadiance r = a.tracePixel(x, y), bare = b.tracePixel(x, y);
            ASSERT_EQ(r.inScattered, glm::dvec3(0.0)) << x << "," << y;
            for (int c = 0; c < 3; ++c) EXPECT_EQ(r.radiance[c], r.transmittance * r.surface[c]);
            if (!r.hitMesh || r.transmittance == 0.0) continue;
            const glm::dvec3 hitPoint = reference::cameraRay(reference::makeCameraFrame(s.camera, w, h), x, y).origin +
                                        r.distance * reference::cameraRay(reference::makeCameraFrame(s.camera, w, h), x, y).direction;
            if (particlesOnLine(s.particles, hitPoint, toSun).empty()) {
                ++unshadowed;
                for (int c = 0; c < 3; ++c) {
                    const double e = std::abs(r.surface[c] - bare.surface[c]) / bare.surface[c];
                    worst = std::max(worst, e);
                    EXPECT_LT(e, 1e-5) << x << "," << y;  // the same point up to the hit's float rounding
                }
            } else {
                ++shadowed;
                EXPECT_LE(r.surface.x, bare.surface.x * (1.0 + 1e-6));
            }
        }
    std::printf("albedo 0: no in-scattering; unshadowed surfaces match the bare scene to %.3g (%d pixels, %d in the medium's shadow)\n",
                worst, unshadowed, shadowed);
    EXPECT_GT(unshadowed, 100);
    EXPECT_GT(shadowed, 10);
}

TEST(ReferenceAnalytic, SlabLitAlongTheViewMatchesItsClosedForm) {
    // An orthographic camera looks straight down on a slab of many particles over a grey ground; the
    // sun shines straight down too, so the light path from any point is the view ray reversed:
    //   L = a p(cosθ = -1) E (1 - exp(-2τ))/2 + f E exp(-2τ)   (τ: the pixel's optical depth)
    // for any density profile, homogeneous or not. f is the glTF BRDF of the rough dielectric ground
    // seen and lit head-on: F = 0.04, D = 1/π, Vis = 1/4, so f = (0.96 ρ + 0.04/4)/π.
    TestScene s;
    const float rho = 0.5f;
    const int ground = s.builder.addMaterial(glm::vec3(rho));
    s.builder.addMesh({fixtures::quad({-10, 0, 10}, {20, 0, 0}, {0, 0, -20}, ground)});
    const float lux = 4.0f, albedo = 0.8f, g = 0.35f;
    s.lights = {fixtures::sun({0.0, -1.0, 0.0}, lux)};
    const Medium m = medium(albedo, g);
    for (int i = -8; i <= 8; ++i)  // a lattice: slab 1 m < y < 3 m, 0.5 m spacing, R = 0.75 m
        for (int j = -8; j <= 8; ++j)
            for (int k = 0; k < 5; ++k) s.particles.push({0.5 * i, 1.0 + 0.5 * k, 0.5 * j}, 0.75f, 0.6f, m);
    s.camera = fixtures::orthographic({0.0, 6.0, 0.0}, {0.0, 0.0, 0.0}, 2.5, 2.5, {0.0, 0.0, -1.0});
    const int w = 24, h = 24;
    const auto in = s.inputs();
    const ReferenceRenderer renderer(in, settings(w, h));
    const assets::RgbImage image = renderer.render();
    const double p = henyeyGreenstein(-1.0, g);
    double worst = 0.0, minTau = 1e9, maxTau = 0.0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const reference::CameraRay ray = reference::cameraRay(reference::makeCameraFrame(s.camera, w, h), x, y);
            const long double tau = numericOpticalDepth(s.particles, ray.origin, ray.direction, 6.0);
            minTau = std::min(minTau, double(tau));
            maxTau = std::max(maxTau, double(tau));
            const long double twoWay = std::exp(-2.0L * tau);
            const long double f = (0.96L * rho + 0.01L) / kPi;
            const long double expected = albedo * p * lux * (1.0L - twoWay) / 2.0L + f * lux * twoWay;
            const double e = relative(image.at(x, y).x, expected);
            worst = std::max(worst, e);
            ASSERT_LT(e, 1e-3) << x << "," << y;
        }
    std::printf("slab single scattering: worst relative error %.3g (tau %.2f..%.2f)\n", worst, minTau, maxTau);
    EXPECT_GT(minTau, 1.0);  // a real slab, not a wisp
}

// Brute force for one ray: L = ∫ T(0,t) Σ_i σ_i ρ_i [a_i(Σ_l p_i E_l T_l + L_amb) + e_i] dt + T(0,∞)·background,
// every transmittance by nested quadrature (no closed form anywhere).
glm::dvec3 bruteForce(const TestScene& s, const glm::dvec3& o, const glm::dvec3& d) {
    const ParticleSet& set = s.particles;
    const std::vector<double> breaks = chordBreaks(set, o, d, 1e30);
    const glm::dvec3 ambient(s.builder.scene.environment.ambient), background(s.builder.scene.environment.background);
    glm::dvec3 total(0.0);
    for (int c = 0; c < 3; ++c) {
        long double sum = 0.0L;
        for (std::size_t k = 0; k + 1 < breaks.size(); ++k)
            sum += integrate(
                [&](long double tl) {
                    const double t = static_cast<double>(tl);
                    const glm::dvec3 x = o + t * d;
                    const long double T = std::exp(-numericOpticalDepth(set, o, d, t, 8));
                    long double source = 0.0L;
                    for (std::size_t i = 0; i < set.size(); ++i) {
                        const glm::dvec3 v = x - set.position[i];
                        const double w = set.sigma[i] * kernelDensity(glm::dot(v, v), set.radius[i]);
                        if (w == 0.0) continue;
                        long double lit = ambient[c];
                        for (const assets::ResolvedLight& l : s.lights) {
                            const assets::LightSample ls = assets::sampleLight(l, x);
                            const double cosTheta = glm::dot(ls.toLight, d);
                            const long double Tl = std::exp(-numericOpticalDepth(set, x, ls.toLight, ls.distance, 8));
                            lit += phaseValue(set.phase[i], set.g[i], cosTheta) * ls.irradiance[c] * Tl;
                        }
                        source += w * (set.albedo[i][c] * lit + set.emission[i][c]);
                    }
                    return T * source;
                },
                breaks[k], breaks[k + 1], 12);
        total[c] = static_cast<double>(sum + std::exp(-numericOpticalDepth(set, o, d, 1e30)) * background[c]);
    }
    return total;
}

TEST(ReferenceAnalytic, MixedMediaUnderSunAndPointLightMatchBruteForce) {
    TestScene s;
    s.builder.scene.environment.background = glm::vec3(0.05f, 0.1f, 0.2f);
    s.builder.scene.environment.ambient = glm::vec3(0.2f, 0.15f, 0.1f);
    s.lights = {fixtures::sun({0.5, -1.0, -0.4}, 3.0f, {1.0f, 0.9f, 0.8f})};
    assets::ResolvedLight lamp;
    lamp.params.type = assets::LightType::Point;
    lamp.params.intensity = 20.0f;
    lamp.params.color = {0.6f, 0.8f, 1.0f};
    lamp.position = {2.5, 1.0, 1.0};
    s.lights.push_back(lamp);
    Medium hg = medium(0.85f, 0.6f);
    hg.albedo = {0.9f, 0.7f, 0.5f};
    const Medium rayleigh = medium(0.95f, 0.0f, glm::vec3(0.0f), PhaseFunction::Rayleigh);
    const Medium fire = medium(0.3f, -0.3f, glm::vec3(2.0f, 0.8f, 0.1f));
    s.particles.push({0.0, 0.0, 0.0}, 1.2f, 1.5f, hg);
    s.particles.push({0.6, 0.3, 0.2}, 0.8f, 3.0f, rayleigh);
    s.particles.push({-0.5, -0.2, 0.4}, 0.5f, 4.0f, fire);
    const auto in = s.inputs();
    const ReferenceRenderer renderer(in, settings(8, 8));
    const glm::dvec3 eye(0.3, 0.2, 6.0);
    double worst = 0.0;
    for (const glm::dvec3 target : {glm::dvec3(0.0), glm::dvec3(0.5, 0.2, 0.0), glm::dvec3(-0.4, -0.1, 0.3),
                                    glm::dvec3(1.1, 0.25, 0.0), glm::dvec3(0.0, 1.18, 0.0)}) {
        const glm::dvec3 d = glm::normalize(target - eye);
        const reference::RayRadiance r = renderer.traceRay(eye, d, 0.0, std::numeric_limits<double>::infinity());
        const glm::dvec3 expected = bruteForce(s, eye, d);
        for (int c = 0; c < 3; ++c) {
            const double e = std::abs(r.radiance[c] - expected[c]) / expected[c];
            worst = std::max(worst, e);
            EXPECT_LT(e, 2e-4) << "target " << target.x << "," << target.y << " channel " << c << ": " << r.radiance[c]
                               << " vs " << expected[c];
        }
    }
    std::printf("mixed media, sun + point light: worst relative error vs brute force %.3g\n", worst);
}

}  // namespace
}  // namespace nimbus::media::test
