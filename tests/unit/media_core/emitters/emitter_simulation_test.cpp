// Tests plugins/participating_media/core/src/emitters/emitter_simulation.cpp: determinism, spawning,
// motion, ageing and what reaches the renderers.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <numbers>

#include <glm/gtc/matrix_transform.hpp>

#include "emitter_test_util.h"
#include "nimbus/media/emitter_simulation.h"

namespace nimbus::media {
namespace {

using test::bitIdentical;
using test::runSteps;
using test::translation;

constexpr double kDt = 1.0 / 60.0;

// A still emitter: no motion of its own, so a particle stays where it was born.
EmitterDesc still(double rate, double lifetime) {
    EmitterDesc d;
    d.rate = rate;
    d.lifetimeMin = d.lifetimeMax = lifetime;
    return d;
}

// A node that moves, turns and scales over time: exercises every part of the spawn transform.
glm::dmat4 wanderingNode(double t) {
    glm::dmat4 m = glm::translate(glm::dmat4(1.0), glm::dvec3(3.0 * t, std::sin(t), 1e5 - 2.0 * t));
    m = glm::rotate(m, 0.7 * t, glm::dvec3(0.0, 1.0, 0.0));
    return glm::scale(m, glm::dvec3(1.0 + 0.1 * t));
}

TEST(EmitterSimulation, SameDescriptionAndStepsGiveBitIdenticalParticles) {
    for (EmitterPreset p : kEmitterPresets) {
        SCOPED_TRACE(std::string(presetName(p)));
        EmitterDesc d = presetDesc(p);
        d.inheritVelocity = 0.3;
        EmitterSimulation a(d, 5), b(d, 5);
        runSteps(a, 240, kDt, wanderingNode);
        runSteps(b, 240, kDt, wanderingNode);
        ASSERT_GT(a.size(), 0u);
        EXPECT_TRUE(bitIdentical(a.particles(), b.particles()));

        ParticleSet sa, sb;
        const Medium medium{3.0f, glm::vec3(0.8f), 0.3f, glm::vec3(0.0f), PhaseFunction::HenyeyGreenstein};
        a.appendParticles(sa, medium);
        b.appendParticles(sb, medium);
        ASSERT_EQ(sa.size(), sb.size());
        EXPECT_EQ(0, std::memcmp(sa.position.data(), sb.position.data(), sa.size() * sizeof(glm::dvec3)));
        EXPECT_EQ(0, std::memcmp(sa.radius.data(), sb.radius.data(), sa.size() * sizeof(float)));
        EXPECT_EQ(0, std::memcmp(sa.sigma.data(), sb.sigma.data(), sa.size() * sizeof(float)));
        EXPECT_EQ(0, std::memcmp(sa.emission.data(), sb.emission.data(), sa.size() * sizeof(glm::vec3)));
    }
}

TEST(EmitterSimulation, SeedAndNodeIndexChangeTheParticles) {
    EmitterDesc d = presetDesc(EmitterPreset::Smoke);
    EmitterSimulation base(d, 1), otherNode(d, 2);
    d.seed = 1;
    EmitterSimulation otherSeed(d, 1);
    for (EmitterSimulation* s : {&base, &otherNode, &otherSeed}) runSteps(*s, 120, kDt, translation({0, 0, 0}));
    ASSERT_EQ(base.size(), otherSeed.size()) << "the same counts (the rate is deterministic)...";
    EXPECT_FALSE(bitIdentical(base.particles(), otherSeed.particles())) << "...but different particles";
    EXPECT_FALSE(bitIdentical(base.particles(), otherNode.particles()));
}

TEST(EmitterSimulation, SteadyStateCountIsRateTimesLifetime) {
    EmitterSimulation fixed(still(60.0, 2.0));
    runSteps(fixed, 600, kDt, translation({0, 0, 0}));
    EXPECT_NEAR(static_cast<double>(fixed.size()), 120.0, 1.0);

    EmitterDesc d = still(60.0, 2.0);
    d.lifetimeMin = 1.0;
    d.lifetimeMax = 3.0;  // mean 2 s
    EmitterSimulation varying(d);
    double sum = 0.0;
    int samples = 0;
    for (int k = 0; k < 3600; ++k) {
        varying.step(k * kDt, kDt, glm::dmat4(1.0), glm::dmat4(1.0));
        if (k >= 600) {
            sum += static_cast<double>(varying.size());
            ++samples;
        }
    }
    EXPECT_NEAR(sum / samples, 120.0, 6.0);
    const auto& age = varying.particles().age;
    const auto& life = varying.particles().lifetime;
    for (std::size_t i = 0; i < varying.size(); ++i) {
        EXPECT_LT(age[i], life[i]);
        EXPECT_GE(life[i], 1.0);
        EXPECT_LE(life[i], 3.0);
    }
}

TEST(EmitterSimulation, SpawnCountFollowsTheRateAcrossSteps) {
    EmitterSimulation s(still(90.0, 100.0));  // 1.5 per step
    for (int k = 0; k < 200; ++k) {
        s.step(k * kDt, kDt, glm::dmat4(1.0), glm::dmat4(1.0));
        const double expected = 90.0 * (k + 1) * kDt;
        EXPECT_LE(std::abs(static_cast<double>(s.spawnedCount()) - expected), 1.0) << "step " << k;
    }
}

TEST(EmitterSimulation, EmissionWindowLimitsSpawning) {
    EmitterDesc d = still(60.0, 100.0);
    d.start = 1.0;
    d.stop = 2.0;
    EmitterSimulation s(d);
    runSteps(s, 60, kDt, translation({0, 0, 0}));
    EXPECT_EQ(s.spawnedCount(), 0u);
    runSteps(s, 300, kDt, translation({0, 0, 0}), 60);
    EXPECT_NEAR(static_cast<double>(s.spawnedCount()), 60.0, 1.0);
    for (double age : s.particles().age) {
        EXPECT_GE(age, 4.0 - 1e-9);  // born in [1, 2), seen at t = 6
        EXPECT_LE(age, 5.0 + 1e-9);
    }
}

TEST(EmitterSimulation, MovingEmitterLeavesAnEvenTrailFarFromTheOrigin) {
    // 30 m/s along +X, 600 particles/s: one particle every 5 cm, ten per step. Interpolating the
    // node inside the step keeps the spacing even; spawning at the step's start would leave 50 cm
    // gaps between clumps of ten.
    EmitterDesc d = still(600.0, 100.0);
    d.maxParticles = 1200;
    EmitterSimulation s(d);
    const glm::dvec3 origin(1e5, 2e3, -1e5);
    runSteps(s, 120, kDt, [&](double t) { return glm::translate(glm::dmat4(1.0), origin + glm::dvec3(30.0 * t, 0, 0)); });
    const auto& p = s.particles().position;
    ASSERT_EQ(p.size(), 1200u);
    const double spacing = 30.0 / 600.0;
    double maxGap = 0.0, minGap = 1e9;
    for (std::size_t i = 1; i < p.size(); ++i) {
        const double gap = glm::length(p[i] - p[i - 1]);
        maxGap = std::max(maxGap, gap);
        minGap = std::min(minGap, gap);
        EXPECT_EQ(p[i].y, origin.y);
    }
    EXPECT_LE(maxGap, spacing + 1e-6);
    EXPECT_GE(minGap, spacing - 1e-6);
    // Births at m/600 s for m = 0 ... 1199: the oldest at the start, the youngest 1/600 s before t = 2 s.
    EXPECT_NEAR(p.front().x - origin.x, 0.0, 1e-6);
    EXPECT_NEAR(p.back().x - origin.x, 60.0 - spacing, 1e-6);
}

TEST(EmitterSimulation, InheritVelocityCarriesTheNodesMotion) {
    EmitterDesc d = still(60.0, 100.0);
    d.inheritVelocity = 0.5;
    EmitterSimulation s(d);
    runSteps(s, 30, kDt, [](double t) { return glm::translate(glm::dmat4(1.0), glm::dvec3(0, 0, -10.0 * t)); });
    for (const glm::dvec3& v : s.particles().velocity) EXPECT_NEAR(glm::distance(v, glm::dvec3(0, 0, -5)), 0.0, 1e-9);
}

TEST(EmitterSimulation, BuoyancyAgainstDragReachesTerminalVelocityAndWindAdvects) {
    EmitterDesc d;
    d.rate = 0.0;
    d.bursts = {{0.0, 1}};
    d.lifetimeMin = d.lifetimeMax = 100.0;
    d.buoyancy = 2.0;
    d.drag = 1.0;
    d.wind = {0.5, 0.0, 0.0};
    EmitterSimulation s(d);
    runSteps(s, 1200, kDt, translation({0, 0, 0}));
    ASSERT_EQ(s.size(), 1u);
    EXPECT_NEAR(s.particles().velocity[0].y, 2.0, 1e-6);  // buoyancy / drag
    EXPECT_EQ(s.particles().velocity[0].x, 0.0) << "wind moves the air, not the particle's own velocity";
    EXPECT_NEAR(s.particles().position[0].x, 0.5 * 20.0, 1e-9);
    // y = ∫ 2(1 − e^{−t}) dt ≈ 2(t − 1) for t = 20 s; the implicit drag lags by O(dt).
    EXPECT_NEAR(s.particles().position[0].y, 38.0, 0.1);
}

TEST(EmitterSimulation, TurbulenceIsSwirlingDivergenceFreeAndOfItsStrength) {
    EmitterDesc d;
    d.turbulence = {0.8, 2.0, 0.5};
    const EmitterSimulation s(d, 3);
    const double h = 1e-3;
    // Around the origin and 1e5 m away: no seam, no loss of precision.
    for (const glm::dvec3 centre : {glm::dvec3(0.0), glm::dvec3(1e5, -3e3, 1e5)}) {
        double sumSq = 0.0, maxDivergence = 0.0, maxGradient = 0.0;
        int n = 0;
        for (int i = -4; i < 4; ++i)
            for (int j = -4; j < 4; ++j)
                for (int k = -4; k < 4; ++k) {
                    const glm::dvec3 x = centre + glm::dvec3(i, j, k) * 0.73;
                    const glm::dvec3 v = s.turbulenceAt(x, 1.5);
                    sumSq += glm::dot(v, v);
                    ++n;
                    double div = 0.0;
                    for (int a = 0; a < 3; ++a) {
                        glm::dvec3 e(0.0);
                        e[a] = h;
                        const glm::dvec3 dv = (s.turbulenceAt(x + e, 1.5) - s.turbulenceAt(x - e, 1.5)) / (2.0 * h);
                        div += dv[a];
                        maxGradient = std::max(maxGradient, glm::length(dv));
                    }
                    maxDivergence = std::max(maxDivergence, std::abs(div));
                }
        const double rms = std::sqrt(sumSq / n);
        EXPECT_GT(rms, 0.6 * 0.8) << "strength is the RMS speed";
        EXPECT_LT(rms, 1.5 * 0.8);
        EXPECT_LT(maxDivergence, 1e-3 * maxGradient) << "a curl has no divergence";
    }
    // The field evolves with time and is zero when off.
    EXPECT_NE(s.turbulenceAt({1.0, 2.0, 3.0}, 0.0), s.turbulenceAt({1.0, 2.0, 3.0}, 3.0));
    EXPECT_EQ(EmitterSimulation(EmitterDesc{}).turbulenceAt({1.0, 2.0, 3.0}, 0.0), glm::dvec3(0.0));
}

// Spawns `count` particles with zero speed in one short step and returns their positions.
std::vector<glm::dvec3> spawnShape(EmitterDesc d, const glm::dmat4& node, std::uint32_t count = 500) {
    d.rate = 0.0;
    d.bursts = {{0.0, count}};
    d.maxParticles = count;
    d.lifetimeMin = d.lifetimeMax = 10.0;
    EmitterSimulation s(d);
    s.step(0.0, 1e-9, node, node);
    return s.particles().position;
}

TEST(EmitterSimulation, SpawnPositionsFillTheShapeInTheNodesFrame) {
    const glm::dvec3 c(10, 20, 30);
    const glm::dmat4 node = glm::scale(glm::translate(glm::dmat4(1.0), c), glm::dvec3(2.0));
    EmitterDesc d;
    d.shape = SpawnShape::Sphere;
    d.shapeRadius = 0.5;
    double maxR = 0.0;
    for (const auto& p : spawnShape(d, node)) maxR = std::max(maxR, glm::distance(p, c));
    EXPECT_LE(maxR, 1.0 + 1e-9);  // 0.5 m × scale 2
    EXPECT_GT(maxR, 0.9);

    d.shape = SpawnShape::Disc;
    for (const auto& p : spawnShape(d, node)) {
        EXPECT_NEAR(p.y, c.y, 1e-9);
        EXPECT_LE(glm::distance(p, c), 1.0 + 1e-9);
    }

    d.shape = SpawnShape::Box;
    d.shapeSize = {1.0, 2.0, 0.5};
    glm::dvec3 lo(1e9), hi(-1e9);
    for (const auto& p : spawnShape(d, node)) {
        lo = glm::min(lo, p - c);
        hi = glm::max(hi, p - c);
    }
    EXPECT_TRUE(glm::all(glm::lessThanEqual(hi, glm::dvec3(1.0, 2.0, 0.5) + 1e-9)));
    EXPECT_TRUE(glm::all(glm::greaterThanEqual(lo, -glm::dvec3(1.0, 2.0, 0.5) - 1e-9)));
    EXPECT_GT(hi.y - lo.y, 3.5);

    d.shape = SpawnShape::Point;
    for (const auto& p : spawnShape(d, node)) EXPECT_EQ(p, c);
}

TEST(EmitterSimulation, DirectionsStayInsideTheSpreadCone) {
    EmitterDesc d;
    d.rate = 0.0;
    d.bursts = {{0.0, 400}};
    d.lifetimeMin = d.lifetimeMax = 10.0;
    d.velocity = {0.0, 0.0, 3.0};
    d.spread = 0.3;
    d.speedJitter = 0.2;
    const glm::dmat4 turned = glm::rotate(glm::dmat4(1.0), std::numbers::pi / 2.0, glm::dvec3(0, 1, 0));  // local +Z → world +X
    EmitterSimulation s(d);
    s.step(0.0, kDt, turned, turned);
    ASSERT_EQ(s.size(), 400u);
    double widest = 0.0;
    for (const glm::dvec3& v : s.particles().velocity) {
        const double speed = glm::length(v);
        EXPECT_GE(speed, 3.0 * 0.8 - 1e-9);
        EXPECT_LE(speed, 3.0 * 1.2 + 1e-9);
        widest = std::max(widest, std::acos(std::clamp(v.x / speed, -1.0, 1.0)));
    }
    EXPECT_LE(widest, 0.3 + 1e-9);
    EXPECT_GT(widest, 0.25);
}

TEST(EmitterSimulation, BurstFiresOnceInTheStepThatHoldsItsTime) {
    EmitterDesc d;
    d.rate = 0.0;
    d.bursts = {{0.105, 50}};
    d.lifetimeMin = d.lifetimeMax = 10.0;
    EmitterSimulation s(d);
    for (int k = 0; k < 60; ++k) {
        s.step(k * kDt, kDt, glm::dmat4(1.0), glm::dmat4(1.0));
        EXPECT_EQ(s.size(), k < 6 ? 0u : 50u) << "step " << k;  // 6/60 <= 0.105 < 7/60
        if (k == 6) {
            for (double age : s.particles().age) EXPECT_NEAR(age, 7.0 / 60.0 - 0.105, 1e-12);
        }
    }
    EXPECT_EQ(s.spawnedCount(), 50u);
}

TEST(EmitterSimulation, ExplosionBurstsThenCoolsIntoRisingSmoke) {
    const EmitterDesc d = presetDesc(EmitterPreset::Explosion);
    EmitterSimulation s(d, 0);
    const Medium medium{4.0f, glm::vec3(1.0f), 0.0f, glm::vec3(0.0f), PhaseFunction::HenyeyGreenstein};
    s.step(0.0, kDt, glm::dmat4(1.0), glm::dmat4(1.0));
    EXPECT_EQ(s.size(), d.bursts[0].count);
    ParticleSet first;
    s.appendParticles(first, medium);
    for (const glm::vec3& e : first.emission) EXPECT_GT(e.x, 5.0f) << "a glowing fireball";

    runSteps(s, 30, kDt, translation({0, 0, 0}), 1);  // t = 0.52 s
    double meanDistance = 0.0;
    for (const auto& p : s.particles().position) meanDistance += glm::length(p) / static_cast<double>(s.size());
    EXPECT_GT(meanDistance, 1.0) << "it expanded fast";

    runSteps(s, 120, kDt, translation({0, 0, 0}), 31);  // t = 2.5 s
    EXPECT_EQ(s.spawnedCount(), d.bursts[0].count) << "the burst fired once";
    ParticleSet later;
    s.appendParticles(later, medium);
    double meanY = 0.0;
    for (std::size_t i = 0; i < later.size(); ++i) {
        EXPECT_EQ(later.emission[i], glm::vec3(0.0f)) << "cooled";
        meanY += later.position[i].y / static_cast<double>(later.size());
    }
    EXPECT_GT(meanY, 1.0) << "the smoke rises";
}

TEST(EmitterSimulation, OutputFollowsTheCurvesOverLife) {
    EmitterDesc d;
    d.rate = 0.0;
    d.bursts = {{0.0, 1}};
    d.lifetimeMin = d.lifetimeMax = 1.0;
    d.radius = {{0.0f, 1.0f}, {1.0f, 3.0f}, };
    d.density = {{0.0f, 1.0f}, {0.0f, 1.0f}};  // ages, values: 0 → 1
    d.albedoOverLife = {{0.0f, 1.0f}, {glm::vec3(0.2f), glm::vec3(0.6f)}};
    d.emissionOverLife = {{0.0f}, {glm::vec3(2.0f, 1.0f, 0.0f)}};
    EmitterSimulation s(d);
    runSteps(s, 30, kDt, translation({0, 0, 0}));  // age 0.5 s
    const Medium medium{4.0f, glm::vec3(0.9f), 0.5f, glm::vec3(0.0f), PhaseFunction::Rayleigh};
    ParticleSet out;
    s.appendParticles(out, medium);
    ASSERT_EQ(out.size(), 1u);
    EXPECT_NEAR(out.radius[0], 2.0f, 1e-5f);
    EXPECT_NEAR(out.sigma[0], 2.0f, 1e-5f);
    EXPECT_NEAR(out.albedo[0].x, 0.4f, 1e-5f);
    EXPECT_EQ(out.emission[0], glm::vec3(2.0f, 1.0f, 0.0f));
    EXPECT_EQ(out.g[0], 0.5f);
    EXPECT_EQ(out.phase[0], PhaseFunction::Rayleigh);

    // Without colour curves the medium's values are used; at density 0 nothing is output.
    d.albedoOverLife = {};
    d.emissionOverLife = {};
    d.radiusJitter = 0.5;
    d.density = {{0.0f, 0.25f, 1.0f}, {0.0f, 0.0f, 1.0f}};  // 0 until a quarter of the life
    EmitterSimulation plain(d);
    ParticleSet none;
    plain.step(0.0, 1e-9, glm::dmat4(1.0), glm::dmat4(1.0));
    plain.appendParticles(none, medium);
    EXPECT_TRUE(none.empty()) << "density 0 at birth";
    runSteps(plain, 30, kDt, translation({0, 0, 0}));
    ParticleSet some;
    plain.appendParticles(some, medium);
    ASSERT_EQ(some.size(), 1u);
    EXPECT_EQ(some.albedo[0], medium.albedo);
    EXPECT_EQ(some.emission[0], medium.emission);
    EXPECT_GE(some.radius[0], 0.5f * 2.0f - 0.01f);
    EXPECT_LE(some.radius[0], 1.5f * 2.0f + 0.01f);
}

TEST(EmitterSimulation, ParticlesDieAtTheirLifetimeAndFullPoolsDrop) {
    EmitterDesc d = still(1000.0, 0.25);
    d.maxParticles = 10;
    EmitterSimulation s(d);
    for (int k = 0; k < 120; ++k) {
        s.step(k * kDt, kDt, glm::dmat4(1.0), glm::dmat4(1.0));
        EXPECT_LE(s.size(), 10u);
        for (std::size_t i = 0; i < s.size(); ++i) EXPECT_LT(s.particles().age[i], 0.25);
    }
    EXPECT_GT(s.droppedCount(), 0u);
    EXPECT_NEAR(static_cast<double>(s.spawnedCount() + s.droppedCount()), 2000.0, 1.0);
}

TEST(EmitterSimulation, AHostStartingLateDoesNotReplayTheBacklog) {
    EmitterSimulation s(still(60.0, 100.0));
    s.step(1000.0, kDt, glm::dmat4(1.0), glm::dmat4(1.0));
    EXPECT_LE(s.spawnedCount(), 3u);  // the births of about one step, not 60 000
    EXPECT_GE(s.spawnedCount(), 1u);
}

TEST(EmitterSimulation, RefusesANonPositiveStep) {
    EmitterSimulation s{EmitterDesc{}};
    EXPECT_THROW(s.step(0.0, 0.0, glm::dmat4(1.0), glm::dmat4(1.0)), std::invalid_argument);
    EXPECT_THROW(s.step(std::nan(""), kDt, glm::dmat4(1.0), glm::dmat4(1.0)), std::invalid_argument);
}

}  // namespace
}  // namespace nimbus::media
