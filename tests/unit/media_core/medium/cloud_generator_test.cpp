// Tests plugins/participating_media/core/src/medium/cloud_generator.cpp: both generators are seeded
// and deterministic, fill what they were asked to, and stay inside their size.
#include "nimbus/media/cloud_generator.h"

#include <gtest/gtest.h>

namespace nimbus::media {
namespace {

void expectInside(const GeneratedCloud& cloud, const CloudGenerator& g) {
    ASSERT_EQ(cloud.positions.size(), static_cast<std::size_t>(g.particles));
    ASSERT_EQ(cloud.radii.size(), cloud.positions.size());
    ASSERT_EQ(cloud.densities.size(), cloud.positions.size());
    for (std::size_t i = 0; i < cloud.positions.size(); ++i) {
        for (int c = 0; c < 3; ++c) EXPECT_LE(std::abs(cloud.positions[i][c]), 0.5 * g.size[c] + 1e-4);
        EXPECT_GE(cloud.radii[i], g.radius.x - 1e-6);
        EXPECT_LE(cloud.radii[i], g.radius.y + 1e-6);
        EXPECT_GT(cloud.densities[i], 0.0f);
        EXPECT_LE(cloud.densities[i], 1.0f);
    }
}

TEST(CloudGenerator, EllipsoidsAreSeededAndInside) {
    const CloudGenerator g{.kind = CloudGeneratorKind::Ellipsoids, .seed = 3, .particles = 2000, .size = {12.0, 7.0, 9.0}, .radius = {0.5, 1.0}};
    const GeneratedCloud a = generateCloud(g), b = generateCloud(g);
    expectInside(a, g);
    EXPECT_EQ(a.positions, b.positions);
    EXPECT_EQ(a.densities, b.densities);
    CloudGenerator other = g;
    other.seed = 4;
    EXPECT_NE(generateCloud(other).positions, a.positions);
    // Gardner's transparency: particles near the surface are thinner than those inside.
    double inner = 0.0, outer = 0.0;
    int innerCount = 0, outerCount = 0;
    for (std::size_t i = 0; i < a.positions.size(); ++i) {
        const double r = glm::length(glm::dvec3(a.positions[i]) / (0.5 * g.size));
        if (r < 0.3) inner += a.densities[i], ++innerCount;
        if (r > 0.8) outer += a.densities[i], ++outerCount;
    }
    ASSERT_GT(innerCount, 0);
    ASSERT_GT(outerCount, 0);
    EXPECT_GT(inner / innerCount, outer / outerCount);
}

TEST(CloudGenerator, DiamondSquareIsALayerWithAFlatBase) {
    const CloudGenerator g{.kind = CloudGeneratorKind::DiamondSquare, .seed = 5, .particles = 3000, .size = {14.0, 4.0, 12.0}, .coverage = 0.4};
    const GeneratedCloud a = generateCloud(g);
    expectInside(a, g);
    EXPECT_EQ(generateCloud(g).positions, a.positions);
    // Every particle sits in a column above the base; the layer's top varies across the map.
    double lowest = 1e9, highest = -1e9;
    for (const glm::vec3& p : a.positions) {
        lowest = std::min(lowest, static_cast<double>(p.y));
        highest = std::max(highest, static_cast<double>(p.y));
    }
    EXPECT_NEAR(lowest, -2.0, 0.1);
    EXPECT_GT(highest, 0.0);
}

}  // namespace
}  // namespace nimbus::media
