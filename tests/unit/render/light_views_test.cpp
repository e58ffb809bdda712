// Light views (render/light_views.h): every point the views must cover lands inside clip space
// [-1,1]² × [0,1], closer to the light means a larger (reversed-Z) depth, and point lights pick
// the cube face cubeFace() names.
#include "nimbus/render/light_views.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>

#include <glm/gtc/constants.hpp>

namespace nimbus::render {
namespace {

constexpr double kSlack = 1e-4;  // float matrices

glm::dvec3 clipOf(const LightView& v, const glm::dvec3& relative) {
    const glm::dvec4 c = glm::dmat4(v.viewProjection) * glm::dvec4(relative, 1.0);
    EXPECT_GT(c.w, 0.0);
    return glm::dvec3(c) / c.w;
}

::testing::AssertionResult insideClip(const glm::dvec3& ndc) {
    if (std::abs(ndc.x) <= 1.0 + kSlack && std::abs(ndc.y) <= 1.0 + kSlack && ndc.z >= -kSlack && ndc.z <= 1.0 + kSlack)
        return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "ndc (" << ndc.x << ", " << ndc.y << ", " << ndc.z << ") outside [-1,1]²×[0,1]";
}

std::array<glm::dvec3, 8> cornersOf(const assets::Aabb& b) {
    std::array<glm::dvec3, 8> c;
    for (int i = 0; i < 8; ++i)
        c[static_cast<std::size_t>(i)] = {i & 1 ? b.max.x : b.min.x, i & 2 ? b.max.y : b.min.y, i & 4 ? b.max.z : b.min.z};
    return c;
}

assets::ResolvedLight directional(const glm::dvec3& travel) {
    assets::ResolvedLight l;
    l.params.type = assets::LightType::Directional;
    l.direction = glm::normalize(travel);
    return l;
}

assets::Aabb box(const glm::dvec3& lo, const glm::dvec3& hi) {
    assets::Aabb b;
    b.extend(lo);
    b.extend(hi);
    return b;
}

TEST(DirectionalLightView, ContainsTheBoundsTightly) {
    const glm::dvec3 origin(1.0e5, -20.0, 3.0e4);  // a camera far from the world origin
    const assets::Aabb bounds = box(origin + glm::dvec3(-8, -1, -3), origin + glm::dvec3(5, 6, 9));
    // Straight down and straight up hit the look-at up-hint degeneracy; the others are generic.
    for (const glm::dvec3 travel : {glm::dvec3(-0.4, -1.0, -0.3), glm::dvec3(0, -1, 0), glm::dvec3(0, 1, 0),
                                    glm::dvec3(1, 0, 0), glm::dvec3(0.3, -0.2, 1.0)}) {
        SCOPED_TRACE(::testing::Message() << "travel " << travel.x << " " << travel.y << " " << travel.z);
        const std::vector<LightView> views = makeLightViews(directional(travel), bounds, origin);
        ASSERT_EQ(views.size(), 1u);
        const LightView& v = views[0];
        EXPECT_FALSE(v.perspective);
        glm::dvec3 lo(1e9), hi(-1e9);
        for (const glm::dvec3& c : cornersOf(bounds)) {
            const glm::dvec3 ndc = clipOf(v, c - origin);
            EXPECT_TRUE(insideClip(ndc));
            lo = glm::min(lo, ndc);
            hi = glm::max(hi, ndc);
        }
        // Fitted, not merely containing: the corners reach the edges of the map and the depth range.
        EXPECT_GT(hi.x, 0.99);
        EXPECT_LT(lo.x, -0.99);
        EXPECT_GT(hi.y, 0.99);
        EXPECT_LT(lo.y, -0.99);
        EXPECT_GT(hi.z, 0.99);
        EXPECT_LT(lo.z, 0.01);
        // Reversed Z: moving towards the light increases depth; lightViewDepth grows along the travel direction.
        const glm::dvec3 centre = bounds.center() - origin;
        const glm::dvec3 towardsLight = centre - glm::normalize(travel);
        EXPECT_GT(clipOf(v, towardsLight).z, clipOf(v, centre).z);
        EXPECT_NEAR(lightViewDepth(v, glm::vec3(centre + glm::normalize(travel))) - lightViewDepth(v, glm::vec3(centre)), 1.0, 1e-3);
    }
}

TEST(DirectionalLightView, RandomBoundsAndDirections) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int i = 0; i < 200; ++i) {
        const glm::dvec3 a(u(rng) * 50, u(rng) * 50, u(rng) * 50), size(std::abs(u(rng)) * 20 + 0.01, std::abs(u(rng)) * 20 + 0.01,
                                                                         std::abs(u(rng)) * 20 + 0.01);
        const double tz = u(rng), ty = u(rng), tx = u(rng);  // in sequence: the same cases from every compiler
        glm::dvec3 travel(tx, ty, tz);
        if (glm::length(travel) < 0.1) travel = {0, -1, 0};
        const assets::Aabb bounds = box(a, a + size);
        const glm::dvec3 origin(u(rng) * 100, u(rng) * 100, u(rng) * 100);
        const std::vector<LightView> views = makeLightViews(directional(travel), bounds, origin);
        ASSERT_EQ(views.size(), 1u);
        for (const glm::dvec3& c : cornersOf(bounds)) EXPECT_TRUE(insideClip(clipOf(views[0], c - origin))) << "case " << i;
    }
}

TEST(SpotLightView, CoversTheConeWithinTheBounds) {
    assets::ResolvedLight spot;
    spot.params.type = assets::LightType::Spot;
    spot.params.outerConeAngle = 0.5;
    spot.params.innerConeAngle = 0.3;
    spot.position = {2.0, 10.0, 1.0};
    spot.direction = glm::normalize(glm::dvec3(0.2, -1.0, 0.1));
    const glm::dvec3 origin(1.0, 2.0, 3.0);
    const assets::Aabb bounds = box({-10, 0, -10}, {10, 3, 10});
    const std::vector<LightView> views = makeLightViews(spot, bounds, origin);
    ASSERT_EQ(views.size(), 1u);
    const LightView& v = views[0];
    EXPECT_TRUE(v.perspective);
    EXPECT_GT(v.halfExtent.x, std::tan(0.5f));  // the whole outer cone fits
    // Points on the outer cone's surface, between the light and the far side of the bounds.
    const glm::dvec3 axis = spot.direction;
    const glm::dvec3 side = glm::normalize(glm::cross(axis, glm::dvec3(1, 0, 0)));
    const glm::dvec3 side2 = glm::cross(axis, side);
    for (int k = 0; k < 16; ++k) {
        const double phi = k * 2.0 * glm::pi<double>() / 16;
        const glm::dvec3 ray = std::cos(0.5) * axis + std::sin(0.5) * (std::cos(phi) * side + std::sin(phi) * side2);
        for (const double distance : {1.0, 5.0, 9.0}) {
            const glm::dvec3 p = spot.position + ray * distance;
            EXPECT_TRUE(insideClip(clipOf(v, p - origin))) << "phi " << phi << " distance " << distance;
        }
    }
    // Depth decreases away from the light (reversed Z); lightViewDepth is the distance along the axis.
    const glm::dvec3 near = spot.position + axis * 2.0 - origin, far = spot.position + axis * 8.0 - origin;
    EXPECT_GT(clipOf(v, near).z, clipOf(v, far).z);
    EXPECT_NEAR(lightViewDepth(v, glm::vec3(far)), 8.0, 1e-4);
    EXPECT_LE(v.depthNear, 2.0f);
    EXPECT_GE(v.depthFar, 8.0f);
}

TEST(PointLightView, SixFacesAndCubeFaceSelectsTheOneContainingThePoint) {
    assets::ResolvedLight point;
    point.params.type = assets::LightType::Point;
    point.position = {0.5, 2.0, -1.0};
    const glm::dvec3 origin(0.2, 0.1, 0.0);
    const assets::Aabb bounds = box({-6, -1, -7}, {5, 8, 4});
    const std::vector<LightView> views = makeLightViews(point, bounds, origin);
    ASSERT_EQ(views.size(), 6u);
    const glm::dvec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (int f = 0; f < 6; ++f) {
        EXPECT_TRUE(views[static_cast<std::size_t>(f)].perspective);
        EXPECT_EQ(cubeFace(glm::vec3(axes[f])), f);
        // The face's axis is the centre of its image.
        const glm::dvec3 ndc = clipOf(views[static_cast<std::size_t>(f)], point.position + axes[f] * 2.0 - origin);
        EXPECT_NEAR(ndc.x, 0.0, 1e-5);
        EXPECT_NEAR(ndc.y, 0.0, 1e-5);
    }
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int i = 0; i < 500; ++i) {
        const double z = u(rng), y = u(rng), x = u(rng);  // in sequence: the same points from every compiler
        const glm::dvec3 p = bounds.min + glm::dvec3(x, y, z) * bounds.extent();
        const glm::dvec3 d = p - point.position;
        if (glm::length(d) < 0.05) continue;
        const int face = cubeFace(glm::vec3(d));
        ASSERT_GE(face, 0);
        ASSERT_LT(face, 6);
        EXPECT_TRUE(insideClip(clipOf(views[static_cast<std::size_t>(face)], p - origin))) << "point " << i << " face " << face;
    }
}

// The shaders find a point's place in a cube face without its matrices: the swizzle must be the
// face's view exactly, and its ndc (xy / z) the projection's.
TEST(CubeFaceView, IsTheFaceViewWithoutItsMatrices) {
    assets::ResolvedLight point;
    point.params.type = assets::LightType::Point;
    point.position = {1.5, -2.0, 0.5};
    const glm::dvec3 origin(0.3, -0.2, 0.1);
    const std::vector<LightView> views = makeLightViews(point, box({-4, -5, -3}, {6, 3, 4}), origin);
    ASSERT_EQ(views.size(), 6u);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int i = 0; i < 300; ++i) {
        const double x = u(rng), y = u(rng), z = u(rng);
        const glm::dvec3 d(x, y, z);
        if (glm::length(d) < 0.05) continue;
        const int face = cubeFace(glm::vec3(d));
        const LightView& v = views[static_cast<std::size_t>(face)];
        const glm::dvec3 p = point.position + d - origin;
        const glm::vec3 c = cubeFaceView(face, glm::vec3(d));
        const glm::vec4 inView = v.view * glm::vec4(glm::vec3(p), 1.0f);
        EXPECT_NEAR(c.x, inView.x, 1e-5) << "point " << i << " face " << face;
        EXPECT_NEAR(c.y, inView.y, 1e-5) << "point " << i << " face " << face;
        EXPECT_NEAR(c.z, -inView.z, 1e-5) << "point " << i << " face " << face;
        const glm::dvec3 ndc = clipOf(v, p);
        EXPECT_NEAR(c.x / c.z, ndc.x, 1e-5);
        EXPECT_NEAR(c.y / c.z, ndc.y, 1e-5);
    }
}

TEST(CubeFaceView, ItsFacesAreCubeFacesAndOthersAreNot) {
    assets::ResolvedLight point;
    point.params.type = assets::LightType::Point;
    point.position = {0.5, 1.0, -2.0};
    const std::vector<LightView> views = makeLightViews(point, box({-3, -3, -3}, {3, 3, 3}), glm::dvec3(0.1, 0.0, 0.2));
    ASSERT_EQ(views.size(), 6u);
    for (int f = 0; f < 6; ++f) {
        EXPECT_TRUE(isCubeFaceView(f, views[static_cast<std::size_t>(f)])) << "face " << f;
        EXPECT_FALSE(isCubeFaceView((f + 1) % 6, views[static_cast<std::size_t>(f)])) << "face " << f << " read as the next";
    }
    LightView turned = views[0];  // +X, rolled a quarter turn about its axis
    const glm::mat4 roll(glm::vec4(0, 1, 0, 0), glm::vec4(-1, 0, 0, 0), glm::vec4(0, 0, 1, 0), glm::vec4(0, 0, 0, 1));
    turned.view = roll * turned.view;
    EXPECT_FALSE(isCubeFaceView(0, turned));
}

TEST(CubeFace, PicksTheDominantAxis) {
    EXPECT_EQ(cubeFace({1.0f, 0.5f, 0.2f}), 0);
    EXPECT_EQ(cubeFace({-2.0f, 1.0f, 1.0f}), 1);
    EXPECT_EQ(cubeFace({0.1f, 3.0f, -1.0f}), 2);
    EXPECT_EQ(cubeFace({0.0f, -1.0f, 0.0f}), 3);
    EXPECT_EQ(cubeFace({0.0f, 0.0f, 1.0f}), 4);
    EXPECT_EQ(cubeFace({0.1f, 0.2f, -5.0f}), 5);
}

TEST(LightViews, EmptyBoundsNeedNoView) {
    EXPECT_TRUE(makeLightViews(directional({0, -1, 0}), assets::Aabb{}, glm::dvec3(0.0)).empty());
}

}  // namespace
}  // namespace nimbus::render
