// Tests sandbox/editor/viewport/picking.cpp: the renderers' pixel convention, projection and ray hits.
#include "viewport/picking.h"

#include <gtest/gtest.h>

#include <cmath>

#include "viewport_test_util.h"

namespace nimbus::sandbox::editor {
namespace {

Aabb box(const glm::dvec3& lo, const glm::dvec3& hi) {
    Aabb b;
    b.extend(lo);
    b.extend(hi);
    return b;
}

TEST(ViewportRay, CentreIsForwardAndCornersMatchTheRenderers) {
    const assets::ResolvedCamera camera = testing::lookAt({1.0, 2.0, 3.0}, {4.0, -1.0, 0.0}, 0.9);
    const Ray centre = viewportRay(camera, {320.0, 240.0}, 640, 480);
    EXPECT_NEAR(glm::length(centre.direction - camera.forward()), 0.0, 1e-12);
    EXPECT_EQ(centre.origin, camera.position());
    // Pixel (0, 0)'s centre, as reference::cameraRay shoots it: row 0 is the top.
    const assets::ResolvedCamera axisCamera = testing::lookAt({0.0, 0.0, 0.0}, {0.0, 0.0, -1.0}, 0.9);
    const double tanHalf = std::tan(0.45), aspect = 5.0 / 3.0;
    const Ray corner = viewportRay(axisCamera, {0.5, 0.5}, 5, 3);
    const glm::dvec3 expected = glm::normalize(glm::dvec3(-0.8 * tanHalf * aspect, (2.0 / 3.0) * tanHalf, -1.0));
    EXPECT_NEAR(glm::length(corner.direction - expected), 0.0, 1e-15);
}

TEST(ViewportRay, OrthographicFollowsTheImageAspect) {
    const assets::ResolvedCamera camera = testing::orthographic({0.0, 0.0, 0.0}, {0.0, 0.0, -1.0}, 2.0);
    const Ray ray = viewportRay(camera, {3.5, 1.5}, 4, 2);  // ndc (0.75, -0.5), as in the reference's test
    EXPECT_EQ(ray.direction, glm::dvec3(0.0, 0.0, -1.0));
    EXPECT_NEAR(ray.origin.x, 3.0, 1e-15);
    EXPECT_NEAR(ray.origin.y, -1.0, 1e-15);
    const Ray centre = viewportRay(camera, {2.0, 1.0}, 4, 2);
    EXPECT_NEAR(glm::length(centre.origin), 0.0, 1e-15);
}

TEST(ViewportRay, ProjectionRoundTrips) {
    const assets::ResolvedCamera cameras[] = {testing::lookAt({1.0, 2.0, 3.0}, {4.0, -1.0, 0.0}, 0.9),
                                              testing::orthographic({-3.0, 1.0, 2.0}, {0.0, 0.0, 0.0}, 2.5)};
    const glm::dvec2 pixels[] = {{0.5, 0.5}, {123.25, 47.75}, {639.5, 479.5}, {320.0, 240.0}, {-20.0, 500.0}};
    for (const assets::ResolvedCamera& camera : cameras) {
        for (const glm::dvec2 pixel : pixels) {
            for (const double t : {0.1, 1.0, 37.0}) {
                const Ray ray = viewportRay(camera, pixel, 640, 480);
                const auto back = projectToViewport(camera, ray.origin + t * ray.direction, 640, 480);
                ASSERT_TRUE(back.has_value());
                EXPECT_NEAR(back->x, pixel.x, 1e-9);
                EXPECT_NEAR(back->y, pixel.y, 1e-9);
            }
        }
    }
}

TEST(ViewportRay, PointsBehindTheCameraDoNotProject) {
    const assets::ResolvedCamera camera = testing::lookAt({0.0, 0.0, 0.0}, {0.0, 0.0, -1.0}, 0.9);
    EXPECT_FALSE(projectToViewport(camera, {0.0, 0.0, 1.0}, 100, 100).has_value());
    EXPECT_FALSE(projectToViewport(camera, {5.0, 0.0, 0.0}, 100, 100).has_value());  // depth 0
    EXPECT_TRUE(projectToViewport(camera, {0.0, 0.0, -1e-6}, 100, 100).has_value());
    const assets::ResolvedCamera ortho = testing::orthographic({0.0, 0.0, 0.0}, {0.0, 0.0, -1.0}, 1.0);
    EXPECT_FALSE(projectToViewport(ortho, {0.0, 0.0, 2.0}, 100, 100).has_value());
    EXPECT_NEAR(worldPerPixel(camera, 10.0, 100), 20.0 * std::tan(0.45) / 100.0, 1e-15);
    EXPECT_NEAR(worldPerPixel(ortho, 10.0, 100), 0.02, 1e-15);
}

TEST(IntersectAabb, HitMissInsideAndAxisParallel) {
    const Aabb unit = box({-1.0, -1.0, -1.0}, {1.0, 1.0, 1.0});
    EXPECT_NEAR(*intersectAabb({{0.2, 0.3, 5.0}, {0.0, 0.0, -1.0}}, unit), 4.0, 1e-15);
    EXPECT_NEAR(*intersectAabb({{0.2, 0.3, 5.0}, {0.0, 0.0, -2.0}}, unit), 2.0, 1e-15);  // not unit: ray parameter
    EXPECT_FALSE(intersectAabb({{2.0, 0.3, 5.0}, {0.0, 0.0, -1.0}}, unit).has_value());   // beside, parallel
    EXPECT_FALSE(intersectAabb({{0.2, 0.3, 5.0}, {0.0, 0.0, 1.0}}, unit).has_value());    // pointing away
    EXPECT_FALSE(intersectAabb({{5.0, 5.0, 5.0}, glm::normalize(glm::dvec3(-1.0, 0.0, -1.0))}, unit).has_value());
    EXPECT_EQ(*intersectAabb({{0.2, 0.3, 0.0}, {1.0, 0.0, 0.0}}, unit), 0.0);  // inside
    EXPECT_NEAR(*intersectAabb({{-4.0, 1.0, -1.0}, {1.0, 0.0, 0.0}}, unit), 3.0, 1e-15);  // along an edge
    const glm::dvec3 diagonal = glm::normalize(glm::dvec3(-1.0, -1.0, -1.0));
    EXPECT_NEAR(*intersectAabb({{3.0, 3.0, 3.0}, diagonal}, unit), 2.0 * std::sqrt(3.0), 1e-12);
    EXPECT_FALSE(intersectAabb({{0.0, 0.0, 5.0}, {0.0, 0.0, -1.0}}, Aabb{}).has_value());  // empty box
}

TEST(IntersectSphere, HitMissInside) {
    EXPECT_NEAR(*intersectSphere({{0.0, 0.0, 5.0}, {0.0, 0.0, -1.0}}, {0.0, 0.0, 0.0}, 1.0), 4.0, 1e-12);
    EXPECT_EQ(*intersectSphere({{0.0, 0.5, 0.0}, {0.0, 0.0, -1.0}}, {0.0, 0.0, 0.0}, 1.0), 0.0);
    EXPECT_FALSE(intersectSphere({{0.0, 2.0, 5.0}, {0.0, 0.0, -1.0}}, {0.0, 0.0, 0.0}, 1.0).has_value());
    EXPECT_FALSE(intersectSphere({{0.0, 0.0, 5.0}, {0.0, 0.0, 1.0}}, {0.0, 0.0, 0.0}, 1.0).has_value());
    EXPECT_FALSE(intersectSphere({{0.0, 0.0, 5.0}, {0.0, 0.0, 0.0}}, {0.0, 0.0, 0.0}, 1.0).has_value());
}

TEST(Pick, NearestOfOverlappingTargets) {
    const Ray ray{{0.0, 0.0, 10.0}, {0.0, 0.0, -1.0}};
    std::vector<PickTarget> targets;
    targets.push_back({7, box({-1.0, -1.0, -1.0}, {1.0, 1.0, 1.0})});
    targets.push_back({3, box({-2.0, -2.0, -2.0}, {2.0, 2.0, 0.0})});  // overlaps 7, but its front is behind 7's
    targets.push_back({9, box({5.0, 5.0, 5.0}, {6.0, 6.0, 6.0})});     // missed, though nearer
    EXPECT_EQ(pick(ray, targets), 7);
    PickTarget light;
    light.id = 12;
    light.sphere = true;
    light.centre = {0.0, 0.0, 3.0};
    light.radius = 0.25;
    targets.push_back(light);
    EXPECT_EQ(pick(ray, targets), 12);
    EXPECT_EQ(pick({{0.0, 0.0, 10.0}, {0.0, 1.0, 0.0}}, targets), -1);
    EXPECT_EQ(pick(ray, {}), -1);
}

// Looking through a scene camera, the eye sits inside that camera's icon: a click picks what it sees.
TEST(Pick, TheCameraLookedThroughIsNotPicked) {
    const Ray ray{{0.0, 8.5, 12.5}, glm::normalize(glm::dvec3(0.0, -4.5, -12.5))};
    PickTarget eye;
    eye.id = 4;
    eye.sphere = true;
    eye.centre = ray.origin;
    eye.radius = 0.004;
    const std::vector<PickTarget> targets = {eye, {1, box({-3.6, 2.2, -2.6}, {3.6, 5.8, 2.6})}};
    EXPECT_EQ(pick(ray, targets), 1);
    EXPECT_EQ(pick({ray.origin, {0.0, 1.0, 0.0}}, targets), -1);
}

TEST(TransformBox, CornersThroughTheMatrix) {
    const Aabb unit = box({-1.0, -1.0, -1.0}, {1.0, 1.0, 1.0});
    glm::dmat4 world = glm::translate(glm::dmat4(1.0), glm::dvec3(10.0, 0.0, 0.0));
    world = glm::rotate(world, glm::radians(45.0), glm::dvec3(0.0, 0.0, 1.0));
    world = glm::scale(world, glm::dvec3(1.0, 1.0, 3.0));
    const Aabb out = transformBox(unit, world);
    EXPECT_NEAR(out.min.x, 10.0 - std::sqrt(2.0), 1e-12);
    EXPECT_NEAR(out.max.y, std::sqrt(2.0), 1e-12);
    EXPECT_NEAR(out.max.z, 3.0, 1e-12);
    EXPECT_TRUE(transformBox(Aabb{}, world).empty());
}

}  // namespace
}  // namespace nimbus::sandbox::editor
