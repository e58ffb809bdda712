// Moving the occluding mesh moves its shadow on the medium (issue acceptance). The scene
// (tests/data/media_scenes/moving_shadow.gltf) is a uniform slab of particles lit by a sun from
// almost straight above; a box high above it, out of view, shadows part of it. The test renders the
// slab with the box where the file puts it (A: x = -1.5) and again after moving the box's entity in
// the App (B: x = +1.5), between two frames of one Session, as an editor or a game would.
//
// Which pixels are in the box's shadow is predicted from geometry alone: march each pixel's camera
// ray through the particles (exact kernel density, view transmittance), weight each point by what it
// contributes (σ·T_view), and take the share of that weight whose sun ray hits the box. Pixels with
// ≥ 90 % in box A's shadow and ≤ 10 % in box B's must be darker with the box at A than at B (and the
// other way round); the region that darkens (seen in the images alone) must be the region with ≥ 50 %
// in the shadow, sit where it is and move as it moves. The reference renderer is held to the same test, which checks the
// prediction itself.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <optional>

#include "media_test_support.h"
#include "nimbus/media/optics.h"
#include "nimbus/media/particle_bvh.h"
#include "nimbus/media/reference/camera_rays.h"
#include "scene_geometry.h"

namespace nimbus::test::media {
namespace {

constexpr int kWidth = 192, kHeight = 108;
// The occluder: a 1.5 × 0.1 × 3 m box (generate_media_scenes.py moving_shadow) centred at these points.
const glm::dvec3 kBoxHalf(0.75, 0.05, 1.5);
const glm::dvec3 kBoxA(-1.5, 6.0, 0.0), kBoxB(1.5, 6.0, 0.0);
// Shadowed pixels keep the ambient and background only; lit ones add the sun (3 lux, ~10× more).
// Darker means below this fraction of the other frame's luminance.
constexpr double kDarker = 0.7;
// The darkened region against the predicted one: centroids within this many pixels, and this much
// overlap (intersection over union; the pixels along the shadow's edges may fall either way).
constexpr double kCentroidTolerance = 1.5;
constexpr double kMinOverlap = 0.85;

struct Prediction {
    std::vector<double> fractionA, fractionB;  // share of the pixel's medium weight in box A's / B's shadow
    std::vector<double> opacity;               // 1 - T_view through the medium
};

std::optional<std::pair<double, double>> slabInterval(const glm::dvec3& o, const glm::dvec3& d, const glm::dvec3& lo,
                                                      const glm::dvec3& hi) {
    double t0 = 0.0, t1 = 1e30;
    for (int i = 0; i < 3; ++i) {
        if (std::abs(d[i]) < 1e-300) {
            if (o[i] < lo[i] || o[i] > hi[i]) return std::nullopt;
            continue;
        }
        double a = (lo[i] - o[i]) / d[i], b = (hi[i] - o[i]) / d[i];
        if (a > b) std::swap(a, b);
        t0 = std::max(t0, a);
        t1 = std::min(t1, b);
    }
    if (t0 >= t1) return std::nullopt;
    return std::make_pair(t0, t1);
}

Prediction predictShadow(const sandbox::ReferenceScene& scene, const glm::dvec3& sunTravel) {
    const nimbus::media::ParticleSet& particles = *scene.inputs.particles;
    const nimbus::media::ParticleBvh bvh(particles);
    const auto frame = nimbus::media::reference::makeCameraFrame(scene.inputs.camera, kWidth, kHeight);
    const assets::Aabb boxA{kBoxA - kBoxHalf, kBoxA + kBoxHalf}, boxB{kBoxB - kBoxHalf, kBoxB + kBoxHalf};
    const glm::dvec3 toSun = -sunTravel;
    Prediction p;
    const std::size_t n = static_cast<std::size_t>(kWidth) * kHeight;
    p.fractionA.assign(n, 0.0);
    p.fractionB.assign(n, 0.0);
    p.opacity.assign(n, 0.0);
    constexpr int kSteps = 160;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            const auto ray = nimbus::media::reference::cameraRay(frame, x, y);
            const auto span = slabInterval(ray.origin, ray.direction, bvh.boundsMin(), bvh.boundsMax());
            if (!span) continue;
            const double dt = (span->second - span->first) / kSteps;
            double tau = 0.0, total = 0.0, inA = 0.0, inB = 0.0;
            for (int s = 0; s < kSteps; ++s) {
                const glm::dvec3 at = ray.origin + ray.direction * (span->first + (s + 0.5) * dt);
                double sigma = 0.0;
                bvh.forEachContaining(at, [&](std::uint32_t i) {
                    const glm::dvec3 v = at - particles.position[i];
                    sigma += particles.sigma[i] * nimbus::media::kernelDensity(glm::dot(v, v), particles.radius[i]);
                    return true;
                });
                const double w = sigma * std::exp(-tau) * dt;
                tau += sigma * dt;
                total += w;
                if (hitBox(at, toSun, boxA)) inA += w;
                if (hitBox(at, toSun, boxB)) inB += w;
            }
            const std::size_t i = static_cast<std::size_t>(y) * kWidth + x;
            p.opacity[i] = -std::expm1(-tau);
            if (total > 0.0) {
                p.fractionA[i] = inA / total;
                p.fractionB[i] = inB / total;
            }
        }
    }
    return p;
}

struct Region {
    std::size_t pixels = 0;
    glm::dvec2 sum{0.0};
    void add(int x, int y) {
        ++pixels;
        sum += glm::dvec2(x + 0.5, y + 0.5);
    }
    glm::dvec2 centroid() const { return pixels > 0 ? sum / double(pixels) : glm::dvec2(-1.0); }
};

// Checks one renderer's pair of frames against the prediction.
void expectShadowFollowsTheBox(const char* renderer, const assets::RgbImage& withA, const assets::RgbImage& withB,
                               const Prediction& p) {
    SCOPED_TRACE(renderer);
    // deep: surely in one box's shadow and surely lit with the other box; half: at least half of the
    // pixel's medium weight in the shadow (where the darkening should end up, edges included).
    Region deepA, deepB, halfA, halfB, darkerA, darkerB;
    std::size_t notDarkerA = 0, notDarkerB = 0, bothA = 0, bothB = 0;
    double worstRatioA = 0.0, worstRatioB = 0.0;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            const std::size_t i = static_cast<std::size_t>(y) * kWidth + x;
            const double la = luminance(withA.at(x, y)), lb = luminance(withB.at(x, y));
            const bool dense = p.opacity[i] >= 0.3, seen = p.opacity[i] >= 0.05;
            if (dense && p.fractionA[i] >= 0.9 && p.fractionB[i] <= 0.1) {
                deepA.add(x, y);
                worstRatioA = std::max(worstRatioA, la / lb);
                if (!(la < kDarker * lb)) ++notDarkerA;
            }
            if (dense && p.fractionB[i] >= 0.9 && p.fractionA[i] <= 0.1) {
                deepB.add(x, y);
                worstRatioB = std::max(worstRatioB, lb / la);
                if (!(lb < kDarker * la)) ++notDarkerB;
            }
            const bool predictedA = seen && p.fractionA[i] >= 0.5, predictedB = seen && p.fractionB[i] >= 0.5;
            const bool observedA = la < kDarker * lb, observedB = lb < kDarker * la;  // the images alone
            if (predictedA) halfA.add(x, y);
            if (predictedB) halfB.add(x, y);
            if (observedA) darkerA.add(x, y);
            if (observedB) darkerB.add(x, y);
            if (predictedA && observedA) ++bothA;
            if (predictedB && observedB) ++bothB;
        }
    }
    ASSERT_GT(deepA.pixels, 200u) << "the scene must put a large shadow in view";
    ASSERT_GT(deepB.pixels, 200u);
    // Every pixel surely in the box's shadow is darker than with the box elsewhere.
    EXPECT_EQ(notDarkerA, 0u) << "of " << deepA.pixels << " pixels in box A's shadow; worst ratio " << worstRatioA;
    EXPECT_EQ(notDarkerB, 0u) << "of " << deepB.pixels << " pixels in box B's shadow; worst ratio " << worstRatioB;
    // The region that darkens is the predicted one (intersection over union), at the predicted place,
    // and it moves by the predicted amount.
    const auto iou = [](std::size_t both, const Region& a, const Region& b) {
        return double(both) / double(a.pixels + b.pixels - both);
    };
    EXPECT_GE(iou(bothA, halfA, darkerA), kMinOverlap) << "A: " << darkerA.pixels << " darker, " << halfA.pixels << " predicted";
    EXPECT_GE(iou(bothB, halfB, darkerB), kMinOverlap) << "B: " << darkerB.pixels << " darker, " << halfB.pixels << " predicted";
    const glm::dvec2 pa = halfA.centroid(), pb = halfB.centroid(), oa = darkerA.centroid(), ob = darkerB.centroid();
    EXPECT_LE(glm::length(oa - pa), kCentroidTolerance) << "A: observed (" << oa.x << ", " << oa.y << "), predicted ("
                                                        << pa.x << ", " << pa.y << ")";
    EXPECT_LE(glm::length(ob - pb), kCentroidTolerance) << "B: observed (" << ob.x << ", " << ob.y << "), predicted ("
                                                        << pb.x << ", " << pb.y << ")";
    EXPECT_GT(ob.x - oa.x, 0.25 * kWidth) << "the shadow moves right with the box";
    EXPECT_LE(glm::length((ob - oa) - (pb - pa)), kCentroidTolerance);
    std::printf("[ measured ] %s: darkened centroid A (%.1f, %.1f) predicted (%.1f, %.1f), IoU %.3f; B (%.1f, %.1f) "
                "predicted (%.1f, %.1f), IoU %.3f; worst luminance ratio in deep shadow %.3f / %.3f\n",
                renderer, oa.x, oa.y, pa.x, pa.y, iou(bothA, halfA, darkerA), ob.x, ob.y, pb.x, pb.y,
                iou(bothB, halfB, darkerB), worstRatioA, worstRatioB);
}

class MovingShadow : public GlSceneTest {};

TEST_F(MovingShadow, MovingTheOccluderMovesTheShadowOnTheMedium) {
    sandbox::Session session(particlesMode(mediaScene("moving_shadow")));
    ecs::World& world = session.app().world();
    const ecs::Entity box = nodeEntity(world, "occluder");
    ASSERT_NE(box, ecs::kNullEntity);
    ASSERT_EQ(glm::dvec3(world.get<scene::Transform>(box).world[3]), kBoxA) << "the scene file and this test disagree";

    const assets::RgbImage realtimeA = session.renderRealtime(kWidth, kHeight);
    const auto sceneA = sandbox::makeReferenceScene(session, "", kWidth, kHeight);
    const assets::RgbImage referenceA = renderReference(session, kWidth, kHeight);
    ASSERT_EQ(sceneA->inputs.lights.size(), 1u);
    const Prediction prediction = predictShadow(*sceneA, sceneA->inputs.lights[0].direction);

    world.get<scene::Transform>(box).world[3] = glm::dvec4(kBoxB, 1.0);
    const assets::RgbImage realtimeB = session.renderRealtime(kWidth, kHeight);
    const assets::RgbImage referenceB = renderReference(session, kWidth, kHeight);

    expectShadowFollowsTheBox("reference", referenceA, referenceB, prediction);
    expectShadowFollowsTheBox("particles", realtimeA, realtimeB, prediction);
}

}  // namespace
}  // namespace nimbus::test::media
