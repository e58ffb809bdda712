// Tests sandbox/editor/viewport/orbit_camera.cpp: starting from a scene camera, orbit, pan, zoom, frame.
#include "viewport/orbit_camera.h"

#include <gtest/gtest.h>

#include <cmath>

#include "viewport/picking.h"
#include "viewport_test_util.h"

namespace nimbus::sandbox::editor {
namespace {

void expectNear(const glm::dvec3& a, const glm::dvec3& b, double tolerance) {
    EXPECT_NEAR(glm::length(a - b), 0.0, tolerance) << "(" << a.x << ", " << a.y << ", " << a.z << ") vs (" << b.x
                                                    << ", " << b.y << ", " << b.z << ")";
}

TEST(OrbitCamera, FromCameraKeepsPositionDirectionAndFov) {
    const assets::ResolvedCamera scene = testing::lookAt({1.0, 2.0, 3.0}, {-2.0, 0.5, -4.0}, 0.7);
    const OrbitCamera orbit = OrbitCamera::fromCamera(scene, 4.0);
    const assets::ResolvedCamera resolved = orbit.resolved();
    expectNear(resolved.position(), scene.position(), 1e-9);
    expectNear(resolved.forward(), scene.forward(), 1e-9);
    expectNear(resolved.up(), scene.up(), 1e-9);
    EXPECT_NEAR(resolved.params.yfov, 0.7, 1e-12);
    expectNear(orbit.target, scene.position() + 4.0 * scene.forward(), 1e-9);
    EXPECT_EQ(resolved.name, "editor");
    EXPECT_EQ(resolved.params.projection, assets::Projection::Perspective);
    EXPECT_FALSE(resolved.synthesized);
}

TEST(OrbitCamera, ResolvedWorldIsRigid) {
    OrbitCamera orbit;
    orbit.yaw = 2.0;
    orbit.pitch = -0.7;
    const glm::dmat3 r(orbit.resolved().world);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(glm::length(r[i]), 1.0, 1e-12);
    EXPECT_NEAR(glm::determinant(r), 1.0, 1e-12);
    expectNear(orbit.resolved().forward(), glm::normalize(orbit.target - orbit.position()), 1e-12);
}

TEST(OrbitCamera, OrbitAndZoomKeepTheTarget) {
    OrbitCamera orbit;
    orbit.target = {1.0, -2.0, 0.5};
    orbit.orbit(35.0, -20.0);
    expectNear(orbit.target, {1.0, -2.0, 0.5}, 0.0);
    EXPECT_NEAR(glm::length(orbit.position() - orbit.target), 5.0, 1e-12);
    EXPECT_NEAR(orbit.yaw, -0.35, 1e-12);
    orbit.zoom(2.0);
    expectNear(orbit.target, {1.0, -2.0, 0.5}, 0.0);
    EXPECT_NEAR(orbit.distance, 5.0 * 0.85 * 0.85, 1e-12);
    orbit.zoom(1000.0);
    EXPECT_GE(orbit.distance, 1e-3);
    orbit.orbit(0.0, 1e6);
    EXPECT_LE(orbit.pitch, OrbitCamera::kMaxPitch);
}

TEST(OrbitCamera, PanMovesThePointUnderTheMouseWithIt) {
    OrbitCamera orbit;
    orbit.yaw = 0.4;
    const glm::dvec3 before = orbit.target;
    orbit.pan(30.0, -12.0, 600);
    EXPECT_GT(glm::length(orbit.target - before), 0.0);
    const auto moved = projectToViewport(orbit.resolved(), before, 800, 600);
    ASSERT_TRUE(moved.has_value());
    EXPECT_NEAR(moved->x, 400.0 + 30.0, 1e-9);
    EXPECT_NEAR(moved->y, 300.0 - 12.0, 1e-9);
}

TEST(OrbitCamera, LookingStraightDownStaysFinite) {
    const assets::ResolvedCamera scene = testing::lookAt({0.0, 5.0, 0.0}, {0.0, 0.0, 0.0}, 0.8, {0.0, 0.0, -1.0});
    OrbitCamera orbit = OrbitCamera::fromCamera(scene, 5.0);
    assets::ResolvedCamera resolved = orbit.resolved();
    EXPECT_TRUE(testing::finite(orbit.target));
    EXPECT_TRUE(testing::finite(resolved.forward()) && testing::finite(resolved.up()));
    expectNear(resolved.position(), scene.position(), 1e-9);
    EXPECT_LT(resolved.forward().y, -0.99);
    EXPECT_GT(glm::dot(resolved.up(), scene.up()), 0.99);  // the picture does not spin
    orbit.orbit(10.0, 10.0);
    orbit.pan(5.0, 5.0, 100);
    resolved = orbit.resolved();
    EXPECT_TRUE(testing::finite(resolved.position()) && testing::finite(resolved.forward()));
    const OrbitCamera up = OrbitCamera::fromCamera(testing::lookAt({0.0, 0.0, 0.0}, {0.0, 3.0, 0.0}, 0.8, {1.0, 0.0, 0.0}), 2.0);
    EXPECT_TRUE(testing::finite(up.resolved().position()));
    EXPECT_GT(up.resolved().forward().y, 0.99);
}

TEST(OrbitCamera, FrameFitsTheBox) {
    OrbitCamera orbit;
    orbit.yaw = 0.8;
    const glm::dvec3 forward = orbit.forward();
    Aabb box;
    box.extend(glm::dvec3(10.0, 20.0, 30.0));
    box.extend(glm::dvec3(14.0, 21.0, 33.0));
    orbit.frame(box);
    expectNear(orbit.target, box.center(), 1e-12);
    expectNear(orbit.forward(), forward, 1e-12);
    const assets::ResolvedCamera camera = orbit.resolved();
    for (int i = 0; i < 8; ++i) {
        const glm::dvec3 corner((i & 1) ? box.max.x : box.min.x, (i & 2) ? box.max.y : box.min.y,
                                (i & 4) ? box.max.z : box.min.z);
        const auto p = projectToViewport(camera, corner, 500, 500);
        ASSERT_TRUE(p.has_value());
        EXPECT_TRUE(p->x >= 0.0 && p->x <= 500.0 && p->y >= 0.0 && p->y <= 500.0) << p->x << ", " << p->y;
    }
    orbit.frame(Aabb{});  // empty: unchanged
    expectNear(orbit.target, box.center(), 0.0);
}

}  // namespace
}  // namespace nimbus::sandbox::editor
