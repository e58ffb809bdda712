// Tests plugins/participating_media/core/src/medium/particle_bvh.cpp against brute force.
#include "nimbus/media/particle_bvh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "nimbus/media/optics.h"

namespace nimbus::media {
namespace {

ParticleSet randomCloud(std::size_t n, unsigned seed, const glm::dvec3& shift = glm::dvec3(0.0)) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> pos(-10.0, 10.0);
    std::uniform_real_distribution<float> rad(0.05f, 2.5f);
    ParticleSet set;
    Medium medium;
    for (std::size_t i = 0; i < n; ++i) set.push(shift + glm::dvec3(pos(rng), pos(rng) * 0.3, pos(rng)), rad(rng), 1.0f, medium);
    return set;
}

std::vector<std::uint32_t> bruteSegment(const ParticleSet& set, const glm::dvec3& o, const glm::dvec3& d, double t0, double t1) {
    std::vector<std::uint32_t> out;
    for (std::uint32_t i = 0; i < set.size(); ++i) {
        const ChordGeometry c = chordGeometry(o, d, set.position[i], set.radius[i]);
        if (c.hit() && c.tExit() > t0 && c.tEnter() < t1) out.push_back(i);
    }
    return out;
}

std::vector<std::uint32_t> sorted(std::vector<std::uint32_t> v) {
    std::sort(v.begin(), v.end());
    return v;
}

TEST(ParticleBvh, SegmentQueriesMatchBruteForce) {
    for (const glm::dvec3 shift : {glm::dvec3(0.0), glm::dvec3(1e5, -2e4, 1e5)}) {
        const ParticleSet set = randomCloud(3000, 7, shift);
        const ParticleBvh bvh(set);
        ASSERT_EQ(bvh.particleCount(), set.size());
        std::mt19937 rng(11);
        std::uniform_real_distribution<double> u(-1.0, 1.0);
        std::size_t found = 0;
        for (int r = 0; r < 400; ++r) {
            const glm::dvec3 o = shift + glm::dvec3(15.0 * u(rng), 5.0 * u(rng), 15.0 * u(rng));
            const double dz = u(rng), dy = u(rng), dx = u(rng);  // in sequence: the same rays from every compiler
            glm::dvec3 d(dx, dy, dz);
            if (r % 7 == 0) d = glm::dvec3(0.0, 0.0, 1.0);  // axis-parallel: slabs with infinite inverse
            if (r % 11 == 0) d = glm::dvec3(0.0, -1.0, 0.0);
            d = glm::normalize(d);
            const double t0 = r % 3 == 0 ? 0.0 : 5.0 * (u(rng) + 1.0);
            const double t1 = r % 5 == 0 ? std::numeric_limits<double>::infinity() : t0 + 20.0 * (u(rng) + 1.0);
            const auto expected = bruteSegment(set, o, d, t0, t1);
            EXPECT_EQ(sorted(bvh.particlesOnSegment(o, d, t0, t1)), expected) << "ray " << r;
            found += expected.size();
        }
        EXPECT_GT(found, 1000u);  // the rays do cross the cloud
    }
}

TEST(ParticleBvh, PointQueriesMatchBruteForce) {
    const ParticleSet set = randomCloud(2000, 3);
    const ParticleBvh bvh(set);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-12.0, 12.0);
    for (int k = 0; k < 500; ++k) {
        const glm::dvec3 x(u(rng), u(rng) * 0.3, u(rng));
        std::vector<std::uint32_t> expected;
        for (std::uint32_t i = 0; i < set.size(); ++i) {
            const glm::dvec3 v = x - set.position[i];
            if (glm::dot(v, v) < double(set.radius[i]) * set.radius[i]) expected.push_back(i);
        }
        EXPECT_EQ(sorted(bvh.particlesContaining(x)), expected);
    }
}

TEST(ParticleBvh, VisitingOrderIsDeterministicAndEarlyExitStops) {
    const ParticleSet set = randomCloud(1000, 9);
    const ParticleBvh a(set), b(set);
    const glm::dvec3 o(-20.0, 0.1, 0.3), d = glm::normalize(glm::dvec3(1.0, 0.01, 0.02));
    EXPECT_EQ(a.particlesOnSegment(o, d, 0.0, 100.0), b.particlesOnSegment(o, d, 0.0, 100.0));
    int visits = 0;
    a.forEachOnSegment(o, d, 0.0, 100.0, [&](std::uint32_t) { return ++visits < 3; });
    EXPECT_EQ(visits, 3);
}

TEST(ParticleBvh, SkipsParticlesWithoutExtinctionAndHandlesEmptySets) {
    ParticleSet set;
    Medium medium;
    set.push({0.0, 0.0, 0.0}, 1.0f, 0.0f, medium);  // sigma 0
    set.push({0.0, 0.0, 5.0}, 0.0f, 1.0f, medium);  // radius 0
    set.push({0.0, 0.0, 9.0}, 1.0f, 2.0f, medium);
    const ParticleBvh bvh(set);
    EXPECT_EQ(bvh.particleCount(), 1u);
    EXPECT_EQ(bvh.particlesOnSegment({0, 0, -5}, {0, 0, 1}, 0.0, 100.0), std::vector<std::uint32_t>{2});
    const ParticleBvh none{ParticleSet{}};
    EXPECT_TRUE(none.empty());
    EXPECT_TRUE(none.particlesOnSegment({0, 0, 0}, {1, 0, 0}, 0.0, 1.0).empty());
    EXPECT_TRUE(none.particlesContaining({0, 0, 0}).empty());
}

}  // namespace
}  // namespace nimbus::media
