// The judge near a light (hard case "a spot light inside the cloud", the reference's side): is the
// reference right, not only converged, where camera rays pass millimetres from a spot light?
//
// spot_near_ray.gltf: a spot light inside a dense particle (σ 73 /m, R 0.82 m, cut by the ground),
// and the camera inside the same particle 0.2 m from the light (an unseen variant that exposed the
// problem, moved to the origin). At 160×90 the rays of the pixels around (98, 7) pass 1–8 mm from
// the light, across the cone's apex.
// What could go wrong: along such a ray the in-scattered light is ρ·p·E·T with E = I/d², a spike
// about as wide as the closest approach b and as high as I/b², on a ray through a medium of optical
// depth ~30. An adaptive quadrature whose first nodes all miss the spike sees a smooth, small
// integrand, its two estimates agree, and it stops: "converged", and wrong by orders of magnitude.
// Halving the tolerance does not find it either, so the harness's self-change check cannot catch it.
// What prevents it: the quadrature's first intervals are cut where the source can spike, at each
// point or spot light's closest approach to the ray and b, 4b, 16b either side of it
// (reference_renderer.cpp lightCuts, medium_quadrature.cpp).
// The check: per pixel, the reference's in-scattered radiance (ReferenceRenderer::tracePixel)
// against an independent brute-force integral of the same model along the same ray — midpoint rule
// in φ (t = t_l + b·tan φ, 20000 nodes) within 0.5 m of the light, 0.2 mm steps elsewhere;
// transmittances in closed form (optics.h), E from assets::sampleLight; the brute force leaves
// meshes out (the ground is below both the light and every lit point). Bound: 1% per pixel (the
// two agree to ~1e-4 where the reference is right).
// Measured (160×90): without the cuts, around (98, 7) the reference gave 0.0099 (the ambient term
// alone) where the brute force gives 3–135 at 12 of the 25 pixels; with them, all 25 agree within
// 1%. Around (98, 20), rays 2.4–3.3 cm from the light, they agreed within 2e-4 either way.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "nimbus/assets/light_model.h"
#include "nimbus/media/optics.h"
#include "nimbus/media/reference/camera_rays.h"
#include "nimbus/media/reference/reference_renderer.h"
#include "stability_harness.h"

namespace nimbus::stability {
namespace {

namespace reference = media::reference;

// In-scattered radiance along origin + t·dir, t in [0, tEnd], by brute force (one light, ambient,
// no meshes): ∫ T(0,t) Σ_i σ_i ρ_i [a_i (p_i(θ) E T_l + L_amb) + e_i] dt.
glm::dvec3 bruteForceInScatter(const media::ParticleSet& particles, const assets::ResolvedLight& light,
                               const glm::dvec3& ambient, const glm::dvec3& origin, const glm::dvec3& dir, double tEnd) {
    auto opticalDepth = [&](const glm::dvec3& from, const glm::dvec3& along, double length) {
        double tau = 0.0;
        for (std::size_t i = 0; i < particles.size(); ++i) {
            const media::ChordGeometry chord = media::chordGeometry(from, along, particles.position[i], particles.radius[i]);
            tau += media::particleOpticalDepth(chord, particles.sigma[i], particles.radius[i], 0.0, length);
        }
        return tau;
    };
    auto integrand = [&](double t) {
        const glm::dvec3 x = origin + t * dir;
        const assets::LightSample sample = assets::sampleLight(light, x);
        const double lightDepth = sample.irradiance == glm::dvec3(0.0) ? 0.0 : opticalDepth(x, sample.toLight, sample.distance);
        const double cosTheta = glm::dot(sample.toLight, dir);  // the reference's convention (reference_renderer.h)
        glm::dvec3 source(0.0);
        for (std::size_t i = 0; i < particles.size(); ++i) {
            const glm::dvec3 d = x - particles.position[i];
            const double sigma = particles.sigma[i] * media::kernelDensity(glm::dot(d, d), particles.radius[i]);
            if (sigma <= 0.0) continue;
            const double phase = media::phaseValue(particles.phase[i], particles.g[i], cosTheta);
            source += sigma * (glm::dvec3(particles.albedo[i]) *
                                   (phase * sample.irradiance * std::exp(-lightDepth) + ambient) +
                               glm::dvec3(particles.emission[i]));
        }
        return source == glm::dvec3(0.0) ? source : source * std::exp(-opticalDepth(origin, dir, t));
    };

    const double tLight = glm::dot(light.position - origin, dir);
    const double b = glm::length(light.position - origin - tLight * dir);
    constexpr double kWindow = 0.5;  // around the light: the φ substitution; elsewhere plain steps
    const double w0 = std::clamp(tLight - kWindow, 0.0, tEnd), w1 = std::clamp(tLight + kWindow, 0.0, tEnd);
    glm::dvec3 sum(0.0);
    auto plain = [&](double a, double c) {
        const int n = static_cast<int>(std::ceil((c - a) / 2e-4));
        for (int k = 0; k < n; ++k) sum += integrand(a + (k + 0.5) * (c - a) / n) * ((c - a) / n);
    };
    plain(0.0, w0);
    const double phi0 = std::atan((w0 - tLight) / b), phi1 = std::atan((w1 - tLight) / b);
    constexpr int kNodes = 20000;
    for (int k = 0; k < kNodes; ++k) {
        const double phi = phi0 + (k + 0.5) * (phi1 - phi0) / kNodes;
        const double c = std::cos(phi);
        sum += integrand(tLight + b * std::tan(phi)) * (b / (c * c) * (phi1 - phi0) / kNodes);
    }
    plain(w1, tEnd);
    return sum;
}

class ReferenceNearLightTest : public StabilityTest {
protected:
    struct PixelCheck {
        int x = 0, y = 0;
        double reference = 0.0, bruteForce = 0.0, closest = 0.0;  // in-scattered radiance (green)
        double particles = 0.0;  // the real-time particles mode's pixel minus the reference's surface term
    };

    // The 5×5 pixels around (cx, cy) of a width×height image of `scene` (no meshes between the light
    // and the medium, which the brute force leaves out).
    static std::vector<PixelCheck> check(const std::filesystem::path& scene, int width, int height, int cx, int cy) {
        sandbox::Session session({scene, 0.0, {}});
        const auto inputs = sandbox::makeReferenceScene(session, "", width, height);
        reference::ReferenceSettings settings;
        settings.scattering = assets::Scattering::Single;  // today's real-time model
        settings.width = width;
        settings.height = height;
        settings.progress = false;
        const reference::ReferenceRenderer renderer(inputs->inputs, settings);
        const reference::CameraFrame frame = reference::makeCameraFrame(inputs->inputs.camera, width, height);
        EXPECT_EQ(inputs->inputs.lights.size(), 1u);
        const assets::ResolvedLight& light = inputs->inputs.lights.front();
        const glm::dvec3 ambient = session.scene().environment.ambient;
        const assets::RgbImage particles = renderMode(session, MediaMode::Particles, width, height, "");
        std::vector<PixelCheck> checks;
        for (int y = cy - 2; y <= cy + 2; ++y) {
            for (int x = cx - 2; x <= cx + 2; ++x) {
                const reference::CameraRay ray = reference::cameraRay(frame, x, y);
                const reference::RayRadiance r = renderer.tracePixel(x, y);
                const double tEnd = std::isfinite(r.distance) ? r.distance : 10.0;  // the particle ends within 5 m
                PixelCheck c;
                c.x = x;
                c.y = y;
                c.reference = r.inScattered.g;
                c.particles = particles.at(x, y).g - (r.radiance.g - r.inScattered.g);
                c.bruteForce =
                    bruteForceInScatter(*inputs->inputs.particles, light, ambient, ray.origin, ray.direction, tEnd).g;
                const double t = glm::dot(light.position - ray.origin, ray.direction);
                c.closest = glm::length(light.position - ray.origin - t * ray.direction);
                checks.push_back(c);
            }
        }
        return checks;
    }
    static std::vector<PixelCheck> check(int cx, int cy) { return check(sceneDirectory() / "spot_near_ray.gltf", 160, 90, cx, cy); }
};

// Rays passing 1–8 mm from the spot light. Before the reference cut its first intervals at each
// point/spot light's closest approach t_l and at t_l ± b, 4b, 16b (reference_renderer.cpp
// lightCuts), it missed the spike altogether (pixel (98, 7): 0.0099 against 107.1).
TEST_F(ReferenceNearLightTest, ReferenceMatchesBruteForceNearSpotLight) {
    for (const PixelCheck& c : check(98, 7)) {
        std::printf("[stability] spot_near_ray pixel (%d, %d), ray %.4f m from the light: reference %.6g, brute force %.6g, "
                    "particles mode %.6g\n",
                    c.x, c.y, c.closest, c.reference, c.bruteForce, c.particles);
        EXPECT_NEAR(c.reference, c.bruteForce, 0.01 * c.bruteForce + 1e-9) << "pixel (" << c.x << ", " << c.y << ")";
    }
}

// What passes today, so that it stays so: pixels whose rays pass 2.4–3.3 cm from the light.
TEST_F(ReferenceNearLightTest, ReferenceMatchesBruteForceAwayFromSpotLight) {
    for (const PixelCheck& c : check(98, 20)) {
        std::printf("[stability] spot_near_ray pixel (%d, %d), ray %.4f m from the light: reference %.6g, brute force %.6g\n",
                    c.x, c.y, c.closest, c.reference, c.bruteForce);
        EXPECT_NEAR(c.reference, c.bruteForce, 0.01 * c.bruteForce + 1e-9)
            << "pixel (" << c.x << ", " << c.y << "), ray " << c.closest << " m from the light";
    }
}

}  // namespace
}  // namespace nimbus::stability
