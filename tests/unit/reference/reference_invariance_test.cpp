// Tests plugins/participating_media/reference/src/reference_renderer.cpp for the properties a judge
// must have: convergence, determinism, symmetry, translation invariance, exact shadow volumes.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>

#include <glm/gtc/matrix_transform.hpp>

#include "nimbus/media/particle_bvh.h"
#include "nimbus/media/reference/image_metrics.h"
#include "reference_fixture.h"

namespace nimbus::media::test {
namespace {

// A small lit cloud over a ground plane with a box that shadows part of it.
TestScene cloudScene(const glm::dvec3& shift = glm::dvec3(0.0), bool mirrorSymmetric = false) {
    TestScene s;
    const int ground = s.builder.addMaterial({0.5f, 0.45f, 0.4f});
    const int red = s.builder.addMaterial({0.8f, 0.2f, 0.1f}, true);
    s.builder.addMesh({fixtures::quad({-15, 0, 15}, {30, 0, 0}, {0, 0, -30}, ground),
                       fixtures::box({-0.75f, 0.0f, -2.5f}, {0.75f, 1.2f, -1.0f}, red)},
                      shift);
    s.builder.scene.environment.background = {0.3f, 0.45f, 0.8f};
    s.builder.scene.environment.ambient = {0.08f, 0.1f, 0.15f};
    s.lights = {fixtures::sun({0.0, -1.0, -0.6}, 3.0f)};
    assets::ResolvedLight lamp;
    lamp.params.type = assets::LightType::Spot;
    lamp.params.intensity = 30.0f;
    lamp.params.outerConeAngle = 0.6;
    lamp.params.innerConeAngle = 0.3;
    lamp.position = shift + glm::dvec3(0.0, 4.0, 3.0);
    lamp.direction = glm::normalize(glm::dvec3(0.0, -1.0, -0.8));
    s.lights.push_back(lamp);
    ParticleSet half;
    addRandomCloud(half, 60, 42, {-3.0, 1.0, -2.0}, {3.0, 3.0, 1.0}, 0.4f, 1.1f, 1.2f, medium(0.9f, 0.5f));
    for (std::size_t i = 0; i < half.size(); ++i) {
        Medium m = medium(half.albedo[i].x, half.g[i]);
        glm::dvec3 p = half.position[i];
        if (mirrorSymmetric) {
            p.x = std::abs(p.x);
            s.particles.push(shift + glm::dvec3(-p.x, p.y, p.z), half.radius[i], half.sigma[i], m);
        }
        s.particles.push(shift + p, half.radius[i], half.sigma[i], m);
    }
    s.camera = fixtures::lookAt(shift + glm::dvec3(0.0, 2.5, 9.0), shift + glm::dvec3(0.0, 1.5, 0.0), 0.8);
    return s;
}

// The largest per-pixel difference, relative to the pixel's brightest channel (what the quadrature's
// tolerance is relative to) or `floor` if that is darker.
double maxRelativeDifference(const assets::RgbImage& a, const assets::RgbImage& b, double floor) {
    double worst = 0.0;
    for (std::size_t p = 0; p < a.pixelCount(); ++p) {
        double scale = floor, difference = 0.0;
        for (std::size_t c = 0; c < 3; ++c) {
            scale = std::max(scale, double(std::abs(b.rgb[3 * p + c])));
            difference = std::max(difference, std::abs(double(a.rgb[3 * p + c]) - b.rgb[3 * p + c]));
        }
        worst = std::max(worst, difference / scale);
    }
    return worst;
}

TEST(ReferenceInvariance, HalvingTheToleranceChangesTheImageByLessThan1e4) {
    TestScene s = cloudScene();
    const auto in = s.inputs();
    const assets::RgbImage a = reference::renderReference(in, settings(48, 32, 1e-4));
    const assets::RgbImage b = reference::renderReference(in, settings(48, 32, 5e-5));
    const assets::RgbImage truth = reference::renderReference(in, settings(48, 32, 1e-7));
    const double change = maxRelativeDifference(a, b, 1e-3);
    const double error = maxRelativeDifference(a, truth, 1e-3);
    std::printf("convergence: tolerance 1e-4 -> 5e-5 changes pixels by <= %.3g; error vs 1e-7: %.3g (rel_rmse %.3g)\n",
                change, error, reference::compareImages(a, truth).relRmse);
    EXPECT_LT(change, 1e-4);
    EXPECT_LT(error, 1e-4);
}

TEST(ReferenceInvariance, SameInputSameBitsWhateverTheThreadCount) {
    TestScene s = cloudScene();
    const auto in = s.inputs();
    const assets::RgbImage one = reference::renderReference(in, settings(40, 24, 1e-4, 1));
    const assets::RgbImage three = reference::renderReference(in, settings(40, 24, 1e-4, 3));
    const assets::RgbImage again = reference::renderReference(in, settings(40, 24, 1e-4, 3));
    ASSERT_EQ(one.rgb.size(), three.rgb.size());
    EXPECT_EQ(std::memcmp(one.rgb.data(), three.rgb.data(), one.rgb.size() * sizeof(float)), 0);
    EXPECT_EQ(std::memcmp(three.rgb.data(), again.rgb.data(), one.rgb.size() * sizeof(float)), 0);
}

TEST(ReferenceInvariance, MirrorSymmetricSceneGivesMirrorSymmetricImage) {
    // The cloud, meshes, camera and lights are symmetric under x -> -x; so must the image be.
    TestScene s = cloudScene(glm::dvec3(0.0), true);
    const auto in = s.inputs();
    const int w = 48, h = 32;
    const assets::RgbImage image = reference::renderReference(in, settings(w, h));
    double worst = 0.0, brightest = 0.0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w / 2; ++x)
            for (int c = 0; c < 3; ++c) {
                const double a = image.at(x, y)[c], b = image.at(w - 1 - x, y)[c];
                worst = std::max(worst, std::abs(a - b) / std::max(std::max(a, b), 1e-3));
                brightest = std::max(brightest, a);
            }
    std::printf("mirror symmetry: worst relative difference %.3g\n", worst);
    EXPECT_LT(worst, 2e-4);  // two independent estimates, each within the tolerance
    EXPECT_GT(brightest, 0.05);
}

TEST(ReferenceInvariance, TranslatedFarFromTheOriginGivesTheSameImage) {
    const glm::dvec3 shift(1e5, 2e4, -1e5);
    TestScene near = cloudScene(), far = cloudScene(shift);
    const auto a = near.inputs(), b = far.inputs();
    const assets::RgbImage imageNear = reference::renderReference(a, settings(48, 32));
    const assets::RgbImage imageFar = reference::renderReference(b, settings(48, 32));
    const reference::ImageMetrics m = reference::compareImages(imageFar, imageNear);
    const double worst = maxRelativeDifference(imageFar, imageNear, 1e-2);
    std::printf("translated by 1e5 m: rel_rmse %.3g, worst pixel %.3g\n", m.relRmse, worst);
    EXPECT_LT(m.relRmse, 1e-3);
    EXPECT_LT(worst, 1e-3);
}

TEST(ReferenceInvariance, ABoxBetweenSunAndCloudDarkensExactlyItsShadowVolume) {
    // An orthographic camera looks along -Z at a slab of cloud; the sun shines straight down. A box
    // above the view (x, z in [-1.5, 1.5]) shadows the columns below it. Pixels whose ray never
    // enters that volume keep the same bits; the others lose exactly the light of the shadowed part.
    TestScene s;
    s.builder.scene.environment.ambient = glm::vec3(0.0f);
    s.lights = {fixtures::sun({0.0, -1.0, 0.0}, 2.0f)};
    const Medium m = medium(0.9f, 0.3f);
    for (int i = -9; i <= 9; ++i)
        for (int k = -9; k <= 9; ++k)
            for (int j = -1; j <= 1; ++j) s.particles.push({0.5 * i, 0.5 * j, 0.5 * k}, 0.7f, 0.35f, m);
    s.camera = fixtures::orthographic({0.0, 0.0, 10.0}, {0.0, 0.0, 0.0}, 5.0, 1.2);
    const int w = 40, h = 12;  // ray x = (px + 0.5)/4 - 5: never within 0.125 of the box's sides ±1.5
    const auto open = s.inputs();
    const assets::RgbImage lit = reference::renderReference(open, settings(w, h));
    s.builder.addMesh({fixtures::box({-1.5f, 3.0f, -1.5f}, {1.5f, 4.0f, 1.5f})});
    const auto boxed = s.inputs();
    const reference::ReferenceRenderer renderer(boxed, settings(w, h));
    const assets::RgbImage shadowed = renderer.render();

    const reference::CameraFrame frame = reference::makeCameraFrame(s.camera, w, h);
    const ParticleBvh bvh(s.particles);
    double worst = 0.0;
    int darker = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const reference::CameraRay ray = reference::cameraRay(frame, x, y);
            if (std::abs(ray.origin.x) > 1.5) {
                for (int c = 0; c < 3; ++c) ASSERT_EQ(shadowed.at(x, y)[c], lit.at(x, y)[c]) << x << "," << y;
                continue;
            }
            // Inside the shadow column: the in-scattering of |z| < 1.5 is gone. Quadrature along the ray
            // of T(0,t) σ a p E T_l over the unshadowed parts, split at the shadow's sides (T and T_l
            // in closed form, which optics_test checks against quadrature; the BVH finds the light's particles).
            const ParticleSet line = particlesOnLine(s.particles, ray.origin, ray.direction);
            const std::vector<double> breaks = chordBreaks(line, ray.origin, ray.direction, 1e30);
            const double p = henyeyGreenstein(glm::dot(glm::dvec3(0, 1, 0), ray.direction), 0.3);
            auto depth = [](const ParticleSet& set, const std::vector<std::uint32_t>& which, const glm::dvec3& o,
                            const glm::dvec3& d, double t1) {
                double tau = 0.0;
                for (const std::uint32_t i : which)
                    tau += particleOpticalDepth(chordGeometry(o, d, set.position[i], set.radius[i]), set.sigma[i],
                                                set.radius[i], 0.0, t1);
                return tau;
            };
            std::vector<std::uint32_t> all(line.size());
            for (std::uint32_t i = 0; i < all.size(); ++i) all[i] = i;
            long double expected = 0.0L;
            for (std::size_t k = 0; k + 1 < breaks.size(); ++k) {
                const double zStart = ray.origin.z - breaks[k], zEnd = ray.origin.z - breaks[k + 1];
                std::vector<double> cuts = {breaks[k], breaks[k + 1]};
                for (double edge : {1.5, -1.5})
                    if (edge < zStart && edge > zEnd) cuts.insert(cuts.end() - 1, ray.origin.z - edge);
                for (std::size_t q = 0; q + 1 < cuts.size(); ++q) {
                    const double zMid = ray.origin.z - 0.5 * (cuts[q] + cuts[q + 1]);
                    if (std::abs(zMid) < 1.5) continue;  // in the box's shadow
                    expected += integrate(
                        [&](long double t) {
                            const glm::dvec3 x3 = ray.origin + static_cast<double>(t) * ray.direction;
                            const double T = std::exp(-depth(line, all, ray.origin, ray.direction, double(t)));
                            const auto above = bvh.particlesOnSegment(x3, {0, 1, 0}, 0.0, 1e30);
                            const double Tl = std::exp(-depth(s.particles, above, x3, {0, 1, 0}, 1e30));
                            return T * extinction(line, x3) * 0.9L * p * 2.0L * Tl;
                        },
                        cuts[q], cuts[q + 1], 6);
                }
            }
            const double value = shadowed.at(x, y).x;
            if (expected > 1e-4L) {
                ++darker;
                EXPECT_LT(value, 0.9 * lit.at(x, y).x) << x << "," << y;
                const double e = static_cast<double>(std::abs((value - expected) / expected));
                worst = std::max(worst, e);
                EXPECT_LT(e, 1e-3) << x << "," << y << ": " << value << " vs " << static_cast<double>(expected);
            } else {
                EXPECT_LT(value, 1e-4) << x << "," << y;
            }
        }
    std::printf("box shadow: %d darkened pixels match brute force within %.3g; all others bit-identical\n", darker, worst);
    EXPECT_GT(darker, 20);
}

}  // namespace
}  // namespace nimbus::media::test
