// Tests that the emitter simulation's memory stays flat however long it runs (McReynolds and Blythe §9's
// particle management: dead particles are recycled, the pool never grows).
#include <gtest/gtest.h>

#include <cmath>

#include "allocation_counter.h"
#include "emitter_test_util.h"
#include "nimbus/media/emitter_simulation.h"

namespace nimbus::media {
namespace {

struct Footprint {
    std::size_t capacity[5];
    const void* data[5];

    explicit Footprint(const EmitterParticles& p)
        : capacity{p.position.capacity(), p.velocity.capacity(), p.age.capacity(), p.lifetime.capacity(),
                   p.sizeScale.capacity()},
          data{p.position.data(), p.velocity.data(), p.age.data(), p.lifetime.data(), p.sizeScale.data()} {}

    bool operator==(const Footprint& o) const {
        for (int i = 0; i < 5; ++i)
            if (capacity[i] != o.capacity[i] || data[i] != o.data[i]) return false;
        return true;
    }
};

TEST(EmitterMemory, HundredThousandStepsKeepThePoolFlatAndAllocateNothing) {
    // A pool that is always full and always churning: 600 spawns/s into 32 slots with short lives,
    // so recycling and dropping both happen every step; bursts, turbulence and a moving node too.
    EmitterDesc d;
    d.maxParticles = 32;
    d.rate = 600.0;
    d.bursts = {{10.0, 30}, {500.0, 32}};
    d.lifetimeMin = 0.02;
    d.lifetimeMax = 0.3;
    d.shape = SpawnShape::Sphere;
    d.velocity = {0.0, 1.0, 0.0};
    d.spread = 1.0;
    d.inheritVelocity = 0.5;
    d.buoyancy = 1.0;
    d.drag = 1.0;
    d.turbulence = {0.5, 1.0, 0.5};
    d.radius = {{0.0f, 0.1f, 1.0f}, {0.5f, 1.5f, 0.2f}};
    d.albedoOverLife = {{0.0f, 1.0f}, {glm::vec3(0.1f), glm::vec3(0.9f)}};
    EmitterSimulation s(d, 7);
    const Medium medium;
    const test::NodePath node = [](double t) {
        return glm::translate(glm::dmat4(1.0), glm::dvec3(10.0 * std::sin(t), 0.0, 10.0 * std::cos(t)));
    };

    constexpr double dt = 1.0 / 60.0;
    constexpr int kWarmUp = 600, kSteps = 100'000;
    test::runSteps(s, kWarmUp, dt, node);
    ParticleSet frame;
    frame.reserve(s.capacity());  // what a host does once: the per-frame output never reallocates either

    const Footprint before(s.particles());
    EXPECT_GE(before.capacity[0], 32u);  // reserved at construction
    const std::uint64_t allocationsBefore = test::allocationCount();
    std::size_t largest = 0;
    for (int k = kWarmUp; k < kWarmUp + kSteps; ++k) {
        const double t0 = static_cast<double>(k) * dt;
        s.step(t0, dt, node(t0), node(static_cast<double>(k + 1) * dt));
        largest = std::max(largest, s.size());
        if (k % 16 == 0) {
            frame.clear();
            s.appendParticles(frame, medium);
        }
    }
    const std::uint64_t allocations = test::allocationCount() - allocationsBefore;

    EXPECT_TRUE(Footprint(s.particles()) == before) << "an SoA array grew or moved";
    EXPECT_EQ(allocations, 0u);
    EXPECT_EQ(largest, 32u) << "the pool was exercised up to its limit, never beyond";
    EXPECT_GT(s.droppedCount(), 0u);
    EXPECT_GT(s.spawnedCount(), 100'000u) << "particles were recycled many times over";
    EXPECT_LE(frame.position.capacity(), 32u);
}

TEST(EmitterMemory, TheCounterSeesAllocations) {
    // The measurement above must be able to fail: a vector that grows is counted.
    const std::uint64_t before = test::allocationCount();
    std::vector<int> v;
    for (int i = 0; i < 100; ++i) v.push_back(i);
    EXPECT_GT(test::allocationCount() - before, 1u);
    EXPECT_EQ(v[99], 99);  // keeps the vector (and its allocations) observable
}

}  // namespace
}  // namespace nimbus::media
