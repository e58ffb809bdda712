// Tests plugins/participating_media/core/src/common/lamp_neighbourhood.cpp: which particles are listed
// around a point or spot light, with which draw rank, and when nothing is listed.
#include "common/lamp_neighbourhood.h"

#include <gtest/gtest.h>

#include <numeric>
#include <vector>

namespace nimbus::media {
namespace {

Light lamp(gpu::LightKind type, glm::dvec3 position) {
    Light light;
    light.kind = type;
    light.position = position;
    return light;
}

ParticleSet particlesAt(const std::vector<glm::dvec3>& centres, float radius) {
    ParticleSet set;
    for (const glm::dvec3& c : centres) set.push(c, radius, 1.0f, Medium{});
    return set;
}

std::vector<std::uint32_t> identityRanks(std::size_t n) {
    std::vector<std::uint32_t> ranks(n);
    std::iota(ranks.begin(), ranks.end(), 0u);
    return ranks;
}

TEST(LampNeighbourhoods, ListsTheParticlesWithinReachWithTheirDrawRank) {
    // Particle 0 contains the lamp (reach = its radius 1); 1 reaches within 1 of the lamp; 2 does not.
    const ParticleSet set = particlesAt({{0.2, 0.0, 0.0}, {1.5, 0.0, 0.0}, {5.0, 0.0, 0.0}}, 1.0f);
    const std::vector<std::uint32_t> ranks{1, 2, 0};  // back to front: 2 first, then 0, then 1
    LampNeighbourhoods n;
    n.find(set, {lamp(gpu::LightKind::Point, {0.0, 0.0, 0.0})}, ranks, LampsListed::InsideMedium);
    ASSERT_EQ(n.lamps.size(), 1u);
    EXPECT_FLOAT_EQ(n.lamps[0].reach, 1.0f);
    ASSERT_EQ(n.lamps[0].count, 2u);
    // Closest relative to the radius first.
    EXPECT_EQ(n.neighbours[n.lamps[0].first].x, 0u);
    EXPECT_EQ(n.neighbours[n.lamps[0].first].y, 1u);
    EXPECT_EQ(n.neighbours[n.lamps[0].first + 1].x, 1u);
    EXPECT_EQ(n.neighbours[n.lamps[0].first + 1].y, 2u);
}

TEST(LampNeighbourhoods, KeepsEachLampsEntriesApartAndInLightOrder) {
    const ParticleSet set = particlesAt({{0.0, 0.0, 0.0}, {10.0, 0.0, 0.0}}, 1.0f);
    LampNeighbourhoods n;
    n.find(set,
           {lamp(gpu::LightKind::Spot, {10.0, 0.0, 0.0}), lamp(gpu::LightKind::Directional, {}),
            lamp(gpu::LightKind::Point, {0.0, 0.0, 0.0})},
           identityRanks(2), LampsListed::InsideMedium);
    ASSERT_EQ(n.lamps.size(), 3u);
    EXPECT_EQ(n.lamps[0].count, 1u);
    EXPECT_EQ(n.neighbours[n.lamps[0].first].x, 1u);
    EXPECT_EQ(n.lamps[1].count, 0u);  // directional: no peak to correct
    EXPECT_EQ(n.lamps[2].count, 1u);
    EXPECT_EQ(n.neighbours[n.lamps[2].first].x, 0u);
}

TEST(LampNeighbourhoods, ListsNothingForALampOutsideTheMedium) {
    const ParticleSet set = particlesAt({{0.0, 0.0, 0.0}}, 1.0f);
    LampNeighbourhoods n;
    n.find(set, {lamp(gpu::LightKind::Point, {1.5, 0.0, 0.0})}, identityRanks(1), LampsListed::InsideMedium);
    ASSERT_EQ(n.lamps.size(), 1u);
    EXPECT_EQ(n.lamps[0].count, 0u);
    EXPECT_TRUE(n.neighbours.empty());
}

TEST(LampNeighbourhoods, GivesALampOutsideTheMediumTheNearestParticlesRadiusWhenAllAreListed) {
    // Blocks mode: the reach ball of a lamp outside the medium is empty or nearly, and that is known.
    const ParticleSet set = particlesAt({{0.0, 0.0, 0.0}, {6.0, 0.0, 0.0}}, 1.0f);
    LampNeighbourhoods n;
    n.find(set, {lamp(gpu::LightKind::Point, {1.8, 0.0, 0.0})}, {7, 3}, LampsListed::All);
    ASSERT_EQ(n.lamps.size(), 1u);
    EXPECT_FLOAT_EQ(n.lamps[0].reach, 1.0f);
    ASSERT_EQ(n.lamps[0].count, 1u);  // particle 0 (gap 0.8) reaches into the ball; 1 (gap 3.2) does not
    EXPECT_EQ(n.neighbours[n.lamps[0].first], glm::uvec2(0u, 7u));
}

TEST(LampNeighbourhoods, ShrinksReachToWhereTheCappedListIsCompleteWhenAllAreListed) {
    // Particles at growing distances; the caller asks for a reach that would take them all. The
    // list keeps the kMaxLampNeighbours nearest by gap, and reach becomes the first gap left out,
    // so every particle reaching into the ball is listed.
    std::vector<glm::dvec3> centres;
    for (std::size_t i = 0; i < kMaxLampNeighbours + 40; ++i) centres.push_back({2.0 + 0.01 * static_cast<double>(i), 0.0, 0.0});
    const ParticleSet set = particlesAt(centres, 1.0f);
    LampNeighbourhoods n;
    n.find(set, {lamp(gpu::LightKind::Point, {0.0, 0.0, 0.0})}, identityRanks(set.size()), LampsListed::All, 10.0);
    ASSERT_EQ(n.lamps[0].count, kMaxLampNeighbours);
    const double firstLeftOut = 2.0 + 0.01 * static_cast<double>(kMaxLampNeighbours) - 1.0;
    EXPECT_NEAR(n.lamps[0].reach, firstLeftOut, 1e-6);
    for (std::uint32_t k = 0; k < n.lamps[0].count; ++k) EXPECT_LT(n.neighbours[n.lamps[0].first + k].x, kMaxLampNeighbours);
}

TEST(LampNeighbourhoods, KeepsTheClosestWhenMoreThanTheCapOverlap) {
    // Many particles all containing the lamp, at growing distances: only the closest are kept.
    std::vector<glm::dvec3> centres;
    for (std::size_t i = 0; i < kMaxLampNeighbours + 40; ++i) centres.push_back({0.001 * static_cast<double>(i), 0.0, 0.0});
    const ParticleSet set = particlesAt(centres, 1.0f);
    LampNeighbourhoods n;
    n.find(set, {lamp(gpu::LightKind::Point, {0.0, 0.0, 0.0})}, identityRanks(set.size()), LampsListed::InsideMedium);
    ASSERT_EQ(n.lamps[0].count, kMaxLampNeighbours);
    for (std::uint32_t k = 0; k < n.lamps[0].count; ++k) EXPECT_LT(n.neighbours[n.lamps[0].first + k].x, kMaxLampNeighbours);
}

TEST(LampNeighbourhoods, DoesNothingWithoutPointOrSpotLights) {
    const ParticleSet set = particlesAt({{0.0, 0.0, 0.0}}, 1.0f);
    LampNeighbourhoods n;
    n.find(set, {lamp(gpu::LightKind::Directional, {})}, identityRanks(1), LampsListed::InsideMedium);
    ASSERT_EQ(n.lamps.size(), 1u);
    EXPECT_EQ(n.lamps[0].count, 0u);
    EXPECT_TRUE(n.neighbours.empty());
}

}  // namespace
}  // namespace nimbus::media
