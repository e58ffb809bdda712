// Tests plugins/participating_media/core/src/common/particle_buffer.cpp visibleDepthOffset: where in front
// of its centre the back-to-front sort puts a particle.
#include "common/particle_buffer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

namespace nimbus::media {
namespace {

// The share of the kernel's optical depth through its centre (cut at ±3 deviations) in front of z.
double kernelShareUpTo(double z) {
    const double edge = std::erf(3.0 / std::sqrt(2.0));
    return (std::erf(z / std::sqrt(2.0)) + edge) / (2.0 * edge);
}

// shaders/media/common/optics.glsl shadingDepthFraction: v̄/τ of a layer of optical depth τ.
double shadingDepthFraction(double tau) { return (1.0 - (1.0 + tau) * std::exp(-tau)) / (tau * -std::expm1(-tau)); }

TEST(VisibleDepthOffset, AThinParticleIsSeenAtItsCentre) {
    EXPECT_EQ(visibleDepthOffset(0.0, 1.0), 0.0);
    EXPECT_EQ(visibleDepthOffset(1e-4, 1.0), 0.0);
    EXPECT_NEAR(visibleDepthOffset(0.05, 1.0), 0.0, 0.01);  // column 0.04: v̄ = τ/2 − τ²/12
}

TEST(VisibleDepthOffset, ItIsWhereTheLayersSeenLightIsCentred) {
    const double radius = 2.0, deviation = radius / 3.0;
    for (double sigma : {0.3, 3.0, 30.0, 300.0, 3e4}) {
        const double column = sigma * deviation * std::sqrt(2.0 * 3.14159265358979);
        const double offset = visibleDepthOffset(sigma, radius);
        EXPECT_GT(offset, 0.0);
        EXPECT_LE(offset, radius);
        EXPECT_NEAR(kernelShareUpTo(-offset / deviation), shadingDepthFraction(column), 1e-6) << "σ " << sigma;
    }
    EXPECT_NEAR(visibleDepthOffset(3e4, radius), radius, 0.25 * deviation) << "a dense particle is seen at its edge";
}

TEST(VisibleDepthOffset, DenserParticlesAreSeenFurtherInFront) {
    double previous = 0.0;
    for (double sigma : {0.5, 2.0, 8.0, 32.0, 128.0, 1e3, 1e5}) {
        const double offset = visibleDepthOffset(sigma, 1.0);
        EXPECT_GT(offset, previous) << "σ " << sigma;
        previous = offset;
    }
}

// sortDescending must give exactly std::stable_sort's order (the exact tier's images depend on it).
TEST(SortDescending, MatchesAStableSortIncludingTiesAndSigns) {
    std::vector<float> keys;
    std::uint32_t state = 12345u;
    for (int i = 0; i < 5000; ++i) {
        state = state * 1664525u + 1013904223u;
        const float value = static_cast<float>(static_cast<int>(state >> 20) - 2048) * 0.25f;  // many ties, both signs
        keys.push_back(i % 97 == 0 ? -0.0f : value);
    }
    keys.push_back(0.0f);
    keys.push_back(3.0e38f);
    keys.push_back(-3.0e38f);
    std::vector<std::uint32_t> expected(keys.size());
    std::iota(expected.begin(), expected.end(), 0u);
    std::stable_sort(expected.begin(), expected.end(), [&](std::uint32_t a, std::uint32_t b) { return keys[a] > keys[b]; });
    std::vector<std::uint32_t> order, scratch;
    sortDescending(keys, order, scratch);
    EXPECT_EQ(order, expected);
}

TEST(SortDescending, HandlesEmptyAndSingle) {
    std::vector<std::uint32_t> order, scratch;
    sortDescending({}, order, scratch);
    EXPECT_TRUE(order.empty());
    sortDescending({1.5f}, order, scratch);
    EXPECT_EQ(order, std::vector<std::uint32_t>{0u});
}

}  // namespace
}  // namespace nimbus::media
