// Reversed-Z projections, depth linearisation, and the pixel-centre ray convention of render/view.h
// (the one the reference renderer uses too, so images compare pixel for pixel).
#include "nimbus/render/view.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include <glm/gtc/matrix_transform.hpp>

namespace nimbus::render {
namespace {

// Depth-buffer value of a point at view depth `z` (distance along forward) through `projection`.
double depthAt(const glm::mat4& projection, double z) {
    const glm::dvec4 clip = glm::dmat4(projection) * glm::dvec4(0.3, -0.2, -z, 1.0);
    return clip.z / clip.w;
}

TEST(ReversedPerspective, MapsNearToOneAndFarToZero) {
    const glm::mat4 p = reversedPerspective(0.9, 1.5, 0.1, 100.0);
    EXPECT_NEAR(depthAt(p, 0.1), 1.0, 1e-6);
    EXPECT_NEAR(depthAt(p, 100.0), 0.0, 1e-6);
    // Monotonic: farther is smaller (GL_GREATER depth test).
    double previous = 2.0;
    for (double z = 0.1; z <= 100.0; z *= 1.7) {
        const double d = depthAt(p, z);
        EXPECT_LT(d, previous) << "z=" << z;
        EXPECT_GE(d, 0.0);
        previous = d;
    }
}

TEST(ReversedPerspective, InfiniteFarPlaneTendsToZero) {
    const glm::mat4 p = reversedPerspective(0.9, 1.5, 0.05, 0.0);
    EXPECT_NEAR(depthAt(p, 0.05), 1.0, 1e-6);
    EXPECT_NEAR(depthAt(p, 1e7), 0.0, 1e-8);
    EXPECT_GT(depthAt(p, 1e7), 0.0) << "infinitely far is the limit, never reached";
    EXPECT_NEAR(depthAt(p, 0.5), 0.1, 1e-6);  // depth = near / z exactly
}

TEST(ReversedPerspective, FieldOfViewAndAspect) {
    const double yfov = 0.8, aspect = 16.0 / 9.0;
    const glm::dmat4 p(reversedPerspective(yfov, aspect, 0.1, 0.0));
    const double t = std::tan(yfov / 2);
    // The top edge of the frustum at depth 3 maps to ndc.y = 1, the right edge to ndc.x = 1.
    const glm::dvec4 top = p * glm::dvec4(0.0, 3.0 * t, -3.0, 1.0);
    const glm::dvec4 right = p * glm::dvec4(3.0 * t * aspect, 0.0, -3.0, 1.0);
    EXPECT_NEAR(top.y / top.w, 1.0, 1e-6);
    EXPECT_NEAR(right.x / right.w, 1.0, 1e-6);
}

TEST(ReversedOrthographic, MapsNearToOneAndFarToZero) {
    const glm::dmat4 p(reversedOrthographic(4.0, 2.0, 1.0, 11.0));
    EXPECT_NEAR(depthAt(glm::mat4(p), 1.0), 1.0, 1e-6);
    EXPECT_NEAR(depthAt(glm::mat4(p), 11.0), 0.0, 1e-6);
    EXPECT_NEAR(depthAt(glm::mat4(p), 6.0), 0.5, 1e-6);
    const glm::dvec4 corner = p * glm::dvec4(4.0, -2.0, -5.0, 1.0);
    EXPECT_NEAR(corner.x, 1.0, 1e-6);
    EXPECT_NEAR(corner.y, -1.0, 1e-6);
    EXPECT_DOUBLE_EQ(corner.w, 1.0);
}

assets::ResolvedCamera perspectiveCamera(double yfov, double znear, double zfar, const glm::dvec3& eye,
                                         const glm::dvec3& target) {
    assets::ResolvedCamera c;
    c.params.yfov = yfov;
    c.params.znear = znear;
    c.params.zfar = zfar;
    c.world = glm::inverse(glm::lookAt(eye, target, glm::dvec3(0.0, 1.0, 0.0)));
    return c;
}

TEST(ViewDepth, InvertsThePerspectiveProjection) {
    for (const double zfar : {0.0, 50.0}) {
        const View v = makeView(perspectiveCamera(0.8, 0.1, zfar, {0, 0, 0}, {0, 0, -1}), 320, 240);
        for (const double z : {0.1, 0.37, 1.0, 4.2, 17.0, 49.0}) {
            const float d = static_cast<float>(depthAt(v.projection, z));
            EXPECT_NEAR(v.viewDepth(d), z, 1e-5 * z * z / 0.1 + 1e-6) << "zfar=" << zfar << " z=" << z;
        }
        EXPECT_NEAR(v.viewDepth(1.0f), 0.1, 1e-7);
    }
    // The cleared reversed-Z buffer (0) is infinitely far with an infinite far plane.
    const View infinite = makeView(perspectiveCamera(0.8, 0.1, 0.0, {0, 0, 0}, {0, 0, -1}), 320, 240);
    EXPECT_EQ(infinite.viewDepth(0.0f), std::numeric_limits<double>::infinity());
}

TEST(ViewDepth, ShaderConstantsGiveTheSameDepth) {
    // GLSL: depth = b / (d + a) for perspective views (frame.glsl uses depthLinearization()).
    const View v = makeView(perspectiveCamera(0.8, 0.2, 80.0, {0, 0, 0}, {0, 0, -1}), 64, 64);
    const glm::vec2 ab = v.depthLinearization();
    for (const float d : {0.01f, 0.2f, 0.5f, 0.99f}) EXPECT_NEAR(ab.y / (d + ab.x), v.viewDepth(d), 1e-4 * v.viewDepth(d));
}

TEST(ViewDepth, InvertsTheOrthographicProjection) {
    assets::ResolvedCamera c;
    c.params.projection = assets::Projection::Orthographic;
    c.params.ymag = 3.0;
    c.params.xmag = 7.0;  // ignored: the image aspect decides the width
    c.params.znear = 0.5;
    c.params.zfar = 40.0;
    const View v = makeView(c, 200, 100);
    EXPECT_TRUE(v.orthographic);
    EXPECT_FLOAT_EQ(v.orthoHalfExtent.x, 6.0f);
    EXPECT_FLOAT_EQ(v.orthoHalfExtent.y, 3.0f);
    for (const double z : {0.5, 3.0, 20.0, 40.0}) {
        const float d = static_cast<float>(depthAt(v.projection, z));
        EXPECT_NEAR(v.viewDepth(d), z, 1e-4) << z;
    }
}

// Pixel (x, y), row 0 at the top, and the point where the world point lands after viewProjection.
glm::dvec2 projectToPixel(const View& v, const glm::dvec3& world) {
    const glm::dvec4 clip = glm::dmat4(v.viewProjection) * glm::dvec4(glm::dvec3(v.toRelative(world)), 1.0);
    const glm::dvec2 ndc(clip.x / clip.w, clip.y / clip.w);
    // GL window coordinates have pixel centres at +0.5 and rows from the bottom.
    return {(ndc.x + 1.0) * 0.5 * v.width - 0.5, (1.0 - ndc.y) * 0.5 * v.height - 0.5};
}

TEST(PixelRays, AWorldPointOnAPixelRayProjectsToThatPixel) {
    // A camera far from the origin, looking down and sideways, with a non-square image.
    const glm::dvec3 eye(1.0e5 + 3.0, 42.0, -2.0e4);
    const assets::ResolvedCamera camera = perspectiveCamera(0.7, 0.05, 0.0, eye, eye + glm::dvec3(-2.0, -1.0, -3.0));
    const int w = 320, h = 180;
    const View v = makeView(camera, w, h);
    const double t = std::tan(camera.params.yfov / 2);
    for (const auto& [x, y] : {std::pair{0, 0}, {w - 1, 0}, {0, h - 1}, {w - 1, h - 1}, {17, 93}, {160, 90}, {301, 5}}) {
        // The formula of view.h.
        const glm::dvec3 dir = camera.forward() + camera.right() * ((2.0 * (x + 0.5) / w - 1.0) * t * w / h) +
                               camera.up() * ((1.0 - 2.0 * (y + 0.5) / h) * t);
        for (const double distance : {0.3, 7.0, 250.0}) {
            const glm::dvec2 p = projectToPixel(v, eye + glm::normalize(dir) * distance);
            EXPECT_NEAR(p.x, x, 2e-3) << "pixel (" << x << ", " << y << ") at " << distance << " m";
            EXPECT_NEAR(p.y, y, 2e-3) << "pixel (" << x << ", " << y << ") at " << distance << " m";
        }
    }
}

TEST(PixelRays, OrthographicPixelCentres) {
    // Orthographic rays are parallel to forward, through origin + right·ndcX·halfWidth + up·ndcY·halfHeight.
    assets::ResolvedCamera camera;
    camera.params.projection = assets::Projection::Orthographic;
    camera.params.ymag = 2.5;
    camera.params.znear = 0.1;
    camera.params.zfar = 100.0;
    camera.world = glm::inverse(glm::lookAt(glm::dvec3(5, 8, 3), glm::dvec3(0, 0, 0), glm::dvec3(0, 1, 0)));
    const int w = 120, h = 80;
    const View v = makeView(camera, w, h);
    for (const auto& [x, y] : {std::pair{0, 0}, {w - 1, h - 1}, {33, 71}}) {
        const double ndcX = 2.0 * (x + 0.5) / w - 1.0, ndcY = 1.0 - 2.0 * (y + 0.5) / h;
        const glm::dvec3 origin = camera.position() + camera.right() * (ndcX * camera.params.ymag * w / h) +
                                  camera.up() * (ndcY * camera.params.ymag);
        const glm::dvec2 p = projectToPixel(v, origin + camera.forward() * 9.0);
        EXPECT_NEAR(p.x, x, 1e-3);
        EXPECT_NEAR(p.y, y, 1e-3);
    }
}

TEST(MakeView, KeepsTheCameraAtTheOriginOfGpuCoordinates) {
    const glm::dvec3 eye(-3.0e5, 10.0, 7.0e4);
    const View v = makeView(perspectiveCamera(0.8, 0.1, 0.0, eye, eye + glm::dvec3(1, 0, 0)), 64, 32);
    EXPECT_EQ(v.origin, eye);
    EXPECT_EQ(v.toRelative(eye), glm::vec3(0.0f));
    // The view matrix is a pure rotation: no translation column.
    EXPECT_EQ(glm::vec3(v.view[3]), glm::vec3(0.0f));
    EXPECT_NEAR(glm::length(glm::dvec3(v.forward) - glm::dvec3(1, 0, 0)), 0.0, 1e-12);
    EXPECT_FLOAT_EQ(v.aspect, 2.0f);
    // inverseViewProjection undoes viewProjection.
    const glm::vec4 p(0.4f, -1.2f, 5.0f, 1.0f);
    const glm::vec4 back = v.inverseViewProjection * (v.viewProjection * p);
    EXPECT_NEAR(back.x / back.w, p.x, 1e-4);
    EXPECT_NEAR(back.y / back.w, p.y, 1e-4);
    EXPECT_NEAR(back.z / back.w, p.z, 1e-4);
}

}  // namespace
}  // namespace nimbus::render
