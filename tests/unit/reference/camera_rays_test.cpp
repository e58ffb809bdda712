// Tests plugins/participating_media/reference/src/camera_rays.cpp: the pixel-centre convention.
#include "nimbus/media/reference/camera_rays.h"

#include <gtest/gtest.h>

#include <cmath>

#include "scene_builder.h"

namespace nimbus::media::reference {
namespace {

TEST(CameraRays, PerspectiveRaysGoThroughPixelCentres) {
    const assets::ResolvedCamera camera = fixtures::lookAt({1.0, 2.0, 3.0}, {1.0, 2.0, -7.0}, 0.9);
    const CameraFrame f = makeCameraFrame(camera, 5, 3);
    const CameraRay centre = cameraRay(f, 2, 1);
    EXPECT_NEAR(centre.direction.z, -1.0, 1e-15);
    EXPECT_EQ(centre.origin, glm::dvec3(1.0, 2.0, 3.0));
    // Top-left pixel: x = 0 is left (-X), row 0 is the top (+Y).
    const double tanHalf = std::tan(0.45), aspect = 5.0 / 3.0;
    const CameraRay corner = cameraRay(f, 0, 0);
    const glm::dvec3 expected = glm::normalize(glm::dvec3(-0.8 * tanHalf * aspect, (2.0 / 3.0) * tanHalf, -1.0));
    EXPECT_NEAR(glm::length(corner.direction - expected), 0.0, 1e-15);
    // The near plane is a plane: t grows off-axis so that the view depth stays znear.
    EXPECT_NEAR(corner.meshNear * glm::dot(corner.direction, f.forward), camera.params.znear, 1e-15);
    EXPECT_TRUE(std::isinf(corner.meshFar));
}

TEST(CameraRays, FarPlaneAndOrthographic) {
    assets::ResolvedCamera camera = fixtures::orthographic({0.0, 0.0, 0.0}, {0.0, 0.0, -1.0}, 4.0, 2.0);
    camera.params.zfar = 50.0;
    const CameraFrame f = makeCameraFrame(camera, 4, 2);
    const CameraRay ray = cameraRay(f, 3, 1);  // ndc (0.75, -0.5)
    EXPECT_EQ(ray.direction, glm::dvec3(0.0, 0.0, -1.0));
    EXPECT_NEAR(ray.origin.x, 3.0, 1e-15);
    EXPECT_NEAR(ray.origin.y, -1.0, 1e-15);
    EXPECT_NEAR(ray.meshFar, 50.0, 1e-12);
}

}  // namespace
}  // namespace nimbus::media::reference
