// Animations read from a file: channels, interpolation modes and key data, and what they do to
// world transforms at hand-computed times (scenes/animated.gltf, see generate_test_data.py).
#include <gtest/gtest.h>

#include <cmath>

#include "asset_test_util.h"
#include "nimbus/assets/scene_queries.h"

namespace nimbus::assets {
namespace {

constexpr double kEps = 1e-6;

glm::dvec3 position(const glm::dmat4& m) { return glm::dvec3(m[3]); }
glm::dvec3 columnLengths(const glm::dmat4& m) {
    return {glm::length(glm::dvec3(m[0])), glm::length(glm::dvec3(m[1])), glm::length(glm::dvec3(m[2]))};
}
void expectNear(const glm::dvec3& a, const glm::dvec3& b, double eps = kEps) {
    EXPECT_NEAR(a.x, b.x, eps);
    EXPECT_NEAR(a.y, b.y, eps);
    EXPECT_NEAR(a.z, b.z, eps);
}

class AnimatedFile : public ::testing::Test {
protected:
    static void SetUpTestSuite() { scene_ = new Scene(loadScene(test::dataPath("scenes/animated.gltf"))); }
    static void TearDownTestSuite() {
        delete scene_;
        scene_ = nullptr;
    }
    static Scene* scene_;
};
Scene* AnimatedFile::scene_ = nullptr;

TEST_F(AnimatedFile, ChannelsAreReadAndTheNodelessOneIgnored) {
    ASSERT_EQ(scene_->animations.size(), 1u);
    const Animation& a = scene_->animations[0];
    EXPECT_EQ(a.name, "All");
    ASSERT_EQ(a.channels.size(), 4u);
    EXPECT_EQ(a.channels[0].node, 0);
    EXPECT_EQ(a.channels[0].path, AnimationPath::Translation);
    EXPECT_EQ(a.channels[0].interpolation, Interpolation::Linear);
    EXPECT_EQ(a.channels[0].times, (std::vector<float>{0.0f, 1.0f, 3.0f}));
    EXPECT_EQ(a.channels[1].interpolation, Interpolation::Step);
    EXPECT_EQ(a.channels[1].path, AnimationPath::Rotation);
    EXPECT_EQ(a.channels[2].interpolation, Interpolation::CubicSpline);
    EXPECT_EQ(a.channels[2].values.size(), 9u);  // in-tangent, value, out-tangent per key
    EXPECT_EQ(a.channels[2].values[2], glm::vec4(3, 0, 0, 0));
    EXPECT_EQ(a.channels[3].node, 4);
}

TEST_F(AnimatedFile, LinearTranslationMovesTheNodeAndItsChild) {
    expectNear(position(computeWorldTransforms(*scene_, 0.5)[0]), {1, 0, 0});
    expectNear(position(computeWorldTransforms(*scene_, 0.5)[1]), {1, 0, 1});  // child offset (0, 0, 1)
    expectNear(position(computeWorldTransforms(*scene_, 2.0)[0]), {2, 2, 0});  // halfway between keys at 1 s and 3 s
    expectNear(position(computeWorldTransforms(*scene_, -1.0)[0]), {0, 0, 0});  // clamped before the first key
    expectNear(position(computeWorldTransforms(*scene_, 10.0)[0]), {2, 4, 0});  // and after the last
}

TEST_F(AnimatedFile, StepRotationHoldsEachKey) {
    auto xAxis = [&](double t) { return glm::dvec3(computeWorldTransforms(*scene_, t)[2][0]); };
    expectNear(xAxis(0.5), {1, 0, 0});   // key 0: identity
    expectNear(xAxis(1.0), {0, 0, -1});  // key 1: 90 degrees about +Y
    expectNear(xAxis(2.9), {0, 0, -1});
    expectNear(xAxis(3.5), {-1, 0, 0});  // key 2: 180 degrees
}

TEST_F(AnimatedFile, CubicSplineScaleFollowsTheHermiteFormula) {
    // s = 0.5 between keys 0 (value 1, out-tangent (3,0,0)) and 1 (value 2, in-tangent 0), dt = 1:
    // 0.5·1 + 0.125·3 + 0.5·2 − 0.125·0 = 1.875 in x; 1.5 in y and z.
    expectNear(columnLengths(computeWorldTransforms(*scene_, 0.5)[3]), {1.875, 1.5, 1.5});
    // Between keys 1 and 2 (dt = 2, zero tangents): plain smoothstep, midpoint 3.
    expectNear(columnLengths(computeWorldTransforms(*scene_, 2.0)[3]), {3, 3, 3});
    expectNear(columnLengths(computeWorldTransforms(*scene_, 0.0)[3]), {1, 1, 1});
}

TEST_F(AnimatedFile, LinearRotationSlerps) {
    const glm::dvec3 x = glm::dvec3(computeWorldTransforms(*scene_, 0.5)[4][0]);
    const double h = std::sqrt(0.5);
    expectNear(x, {h, 0, -h});  // 45 degrees about +Y
}

}  // namespace
}  // namespace nimbus::assets
