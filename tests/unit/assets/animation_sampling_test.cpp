// Channel sampling through computeWorldTransforms on hand-made scenes: clamping, STEP, LINEAR
// (shortest-path slerp), CUBICSPLINE against hand-computed values.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <glm/gtc/quaternion.hpp>

#include "nimbus/assets/scene_queries.h"

namespace nimbus::assets {
namespace {

Scene sceneWith(AnimationChannel channel) {
    Scene scene;
    scene.nodes.resize(1);
    scene.rootNodes = {0};
    channel.node = 0;
    scene.animations.push_back({"a", {std::move(channel)}});
    return scene;
}

glm::dvec3 translationAt(const Scene& s, double t) { return glm::dvec3(computeWorldTransforms(s, t)[0][3]); }
glm::dquat rotationAt(const Scene& s, double t) { return glm::quat_cast(computeWorldTransforms(s, t)[0]); }

AnimationChannel translationChannel(Interpolation interpolation, std::vector<float> times, std::vector<glm::vec4> values) {
    AnimationChannel c;
    c.path = AnimationPath::Translation;
    c.interpolation = interpolation;
    c.times = std::move(times);
    c.values = std::move(values);
    return c;
}

TEST(AnimationSampling, LinearInterpolatesAndClamps) {
    const Scene s = sceneWith(translationChannel(Interpolation::Linear, {1.0f, 2.0f}, {{0, 0, 0, 0}, {4, -2, 8, 0}}));
    EXPECT_EQ(translationAt(s, 1.25), glm::dvec3(1, -0.5, 2));
    EXPECT_EQ(translationAt(s, 0.0), glm::dvec3(0, 0, 0));
    EXPECT_EQ(translationAt(s, 5.0), glm::dvec3(4, -2, 8));
}

TEST(AnimationSampling, StepHoldsUntilTheNextKey) {
    const Scene s = sceneWith(translationChannel(Interpolation::Step, {0.0f, 1.0f, 2.0f}, {{1, 0, 0, 0}, {2, 0, 0, 0}, {3, 0, 0, 0}}));
    EXPECT_EQ(translationAt(s, 0.999).x, 1.0);
    EXPECT_EQ(translationAt(s, 1.0).x, 2.0);
    EXPECT_EQ(translationAt(s, 1.5).x, 2.0);
    EXPECT_EQ(translationAt(s, 7.0).x, 3.0);
}

TEST(AnimationSampling, CubicSplineUsesTangentsScaledByTheInterval) {
    // Keys at t = 0 and 2 (dt = 2): p0 = 0, out-tangent b0 = 1; p1 = 1, in-tangent a1 = -1.
    // s = 0.25: h00 = 0.84375, h10 = 0.140625, h01 = 0.15625, h11 = -0.046875
    // p = 0.84375·0 + 0.140625·(2·1) + 0.15625·1 − 0.046875·(2·−1) = 0.53125
    const Scene s = sceneWith(translationChannel(Interpolation::CubicSpline, {0.0f, 2.0f},
                                                 {{9, 0, 0, 0}, {0, 0, 0, 0}, {1, 0, 0, 0}, {-1, 0, 0, 0}, {1, 0, 0, 0}, {9, 0, 0, 0}}));
    EXPECT_NEAR(translationAt(s, 0.5).x, 0.53125, 1e-12);
    EXPECT_EQ(translationAt(s, 0.0).x, 0.0);  // key values, not tangents, at and beyond the ends
    EXPECT_EQ(translationAt(s, 3.0).x, 1.0);
}

TEST(AnimationSampling, LinearRotationTakesTheShortPath) {
    AnimationChannel c;
    c.path = AnimationPath::Rotation;
    c.times = {0.0f, 1.0f};
    const float h = std::sqrt(0.5f);
    // 0 and 90 degrees about Z, the second written as its negative (same rotation): slerp must not go the long way.
    c.values = {{0, 0, 0, 1}, {0, 0, -h, -h}};
    const Scene s = sceneWith(c);
    const glm::dquat q = rotationAt(s, 0.5);
    const double angle = 2.0 * std::acos(std::min(1.0, std::abs(q.w)));
    EXPECT_NEAR(angle, std::numbers::pi / 4, 1e-6);
    const glm::dvec3 x = glm::dvec3(computeWorldTransforms(s, 0.5)[0][0]);
    EXPECT_NEAR(x.x, std::sqrt(0.5), 1e-6);
    EXPECT_NEAR(x.y, std::sqrt(0.5), 1e-6);
}

TEST(AnimationSampling, CubicRotationIsNormalized) {
    AnimationChannel c;
    c.path = AnimationPath::Rotation;
    c.interpolation = Interpolation::CubicSpline;
    c.times = {0.0f, 1.0f};
    c.values = {{0, 0, 0, 0}, {0, 0, 0, 1}, {0, 0, 0, 0}, {0, 0, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 0}};
    const Scene s = sceneWith(c);
    const glm::dmat4 m = computeWorldTransforms(s, 0.5)[0];
    for (int col = 0; col < 3; ++col) EXPECT_NEAR(glm::length(glm::dvec3(m[col])), 1.0, 1e-12);  // a pure rotation
}

TEST(AnimationSampling, AnimatedValuesReplaceTheRestPoseOnlyOnTheirPath) {
    Scene s = sceneWith(translationChannel(Interpolation::Linear, {0.0f}, {{5, 0, 0, 0}}));
    s.nodes[0].scale = glm::dvec3(2.0);
    const glm::dmat4 m = computeWorldTransforms(s, 0.0)[0];
    EXPECT_EQ(glm::dvec3(m[3]), glm::dvec3(5, 0, 0));
    EXPECT_EQ(glm::length(glm::dvec3(m[0])), 2.0);
}

}  // namespace
}  // namespace nimbus::assets
