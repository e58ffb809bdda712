// sampleLight: inverse square, the glTF range window, the KHR_lights_punctual spot cone, and
// finite results at the light itself.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "nimbus/assets/light_model.h"

namespace nimbus::assets {
namespace {

ResolvedLight pointLight(double intensity, double range = 0.0) {
    ResolvedLight l;
    l.params.type = LightType::Point;
    l.params.intensity = static_cast<float>(intensity);
    l.params.range = range;
    return l;
}

ResolvedLight spotDown(double inner, double outer) {
    ResolvedLight l = pointLight(100.0);
    l.params.type = LightType::Spot;
    l.params.innerConeAngle = inner;
    l.params.outerConeAngle = outer;
    l.position = {0, 10, 0};
    l.direction = {0, -1, 0};
    return l;
}

// A point at distance 10 from the spot, `angle` away from its axis.
glm::dvec3 pointAtAngle(double angle) { return {10 * std::sin(angle), 10 - 10 * std::cos(angle), 0}; }

TEST(LightModel, DirectionalGivesColorTimesIntensityFromBehindItsDirection) {
    ResolvedLight sun;
    sun.params.type = LightType::Directional;
    sun.params.color = {1.0f, 0.5f, 0.25f};
    sun.params.intensity = 4.0f;
    sun.direction = glm::normalize(glm::dvec3(0, -1, -1));
    const LightSample s = sampleLight(sun, {123, 456, 789});
    EXPECT_EQ(s.irradiance, glm::dvec3(4, 2, 1));
    EXPECT_EQ(s.toLight, -sun.direction);
    EXPECT_EQ(s.distance, std::numeric_limits<double>::infinity());
}

TEST(LightModel, PointLightFallsOffWithTheInverseSquare) {
    ResolvedLight l = pointLight(100.0);
    l.position = {1, 2, 3};
    const LightSample near = sampleLight(l, {1, 2, 1});
    EXPECT_DOUBLE_EQ(near.irradiance.x, 25.0);
    EXPECT_EQ(near.distance, 2.0);
    EXPECT_EQ(near.toLight, glm::dvec3(0, 0, 1));
    EXPECT_DOUBLE_EQ(sampleLight(l, {1, 2, -1}).irradiance.y, 6.25);
}

TEST(LightModel, RangeWindowFadesToZeroAtTheRange) {
    const ResolvedLight l = pointLight(100.0, 10.0);
    // d = 5: (1 - 0.5^4)^2 = 0.87890625
    EXPECT_DOUBLE_EQ(sampleLight(l, {5, 0, 0}).irradiance.x, 100.0 / 25.0 * 0.87890625);
    EXPECT_EQ(sampleLight(l, {10, 0, 0}).irradiance.x, 0.0);
    EXPECT_EQ(sampleLight(l, {12, 0, 0}).irradiance.x, 0.0);
    EXPECT_EQ(rangeWindow(3.0, 0.0), 1.0);  // no range: infinite
    EXPECT_DOUBLE_EQ(rangeWindow(5.0, 10.0), 0.87890625);
}

TEST(LightModel, SpotConeIsFullInsideInnerAndZeroOutsideOuter) {
    const ResolvedLight l = spotDown(0.2, 0.6);
    const double full = 100.0 / 100.0;  // intensity / d² at d = 10
    EXPECT_NEAR(sampleLight(l, pointAtAngle(0.0)).irradiance.x, full, 1e-12);
    EXPECT_NEAR(sampleLight(l, pointAtAngle(0.1)).irradiance.x, full, 1e-12);
    EXPECT_NEAR(sampleLight(l, pointAtAngle(0.2)).irradiance.x, full, 1e-9);  // at the inner edge
    EXPECT_NEAR(sampleLight(l, pointAtAngle(0.6)).irradiance.x, 0.0, 1e-9);   // at the outer edge
    EXPECT_EQ(sampleLight(l, pointAtAngle(1.0)).irradiance.x, 0.0);
    EXPECT_EQ(sampleLight(l, {0, 20, 0}).irradiance.x, 0.0);  // behind the spot
    // Between the edges: ((cos θ − cos outer) / (cos inner − cos outer))².
    const double a = (std::cos(0.4) - std::cos(0.6)) / (std::cos(0.2) - std::cos(0.6));
    EXPECT_NEAR(sampleLight(l, pointAtAngle(0.4)).irradiance.x, full * a * a, 1e-12);
}

TEST(LightModel, SpotWithEqualConesDoesNotDivideByZero) {
    const ResolvedLight l = spotDown(0.5, 0.5);
    const double inside = sampleLight(l, pointAtAngle(0.3)).irradiance.x;
    EXPECT_TRUE(std::isfinite(inside));
    EXPECT_NEAR(inside, 1.0, 1e-12);
    EXPECT_EQ(spotAttenuation(std::cos(0.7), 0.5, 0.5), 0.0);
}

TEST(LightModel, PointAtTheLightGetsZeroNotInfinity) {
    ResolvedLight l = pointLight(100.0);
    l.position = {1e5, 0, 0};
    const LightSample s = sampleLight(l, {1e5, 0, 0});
    EXPECT_EQ(s.irradiance, glm::dvec3(0.0));
    EXPECT_TRUE(std::isfinite(s.toLight.x) && std::isfinite(s.toLight.y) && std::isfinite(s.toLight.z));
    EXPECT_NEAR(glm::length(s.toLight), 1.0, 1e-12);
}

TEST(LightModel, ColorScalesEachChannel) {
    ResolvedLight l = pointLight(4.0);
    l.params.color = {1.0f, 0.5f, 0.0f};
    const LightSample s = sampleLight(l, {0, 0, 1});
    EXPECT_EQ(s.irradiance, glm::dvec3(4, 2, 0));
}

}  // namespace
}  // namespace nimbus::assets
