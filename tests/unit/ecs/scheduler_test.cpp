#include "nimbus/ecs/scheduler.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "expect_error.h"
#include "nimbus/ecs/world.h"

namespace nimbus::ecs {
namespace {

using test::throwsLogicError;
using Names = std::vector<std::string>;

// A scheduler whose systems append their names to `ran`.
struct Recorder {
    Scheduler scheduler;
    World world;
    Names ran;

    bool add(std::string name, std::string phase = phases::kSimulate, Names after = {}, Names before = {}) {
        SystemDesc desc{name, std::move(phase), std::move(after), std::move(before)};
        return scheduler.addSystem(std::move(desc), [this, name](World&) { ran.push_back(name); });
    }
};

TEST(Scheduler, DefaultPhasesInOrder) {
    Scheduler s;
    EXPECT_EQ(s.phaseOrder(), (Names{"Startup", "Simulate", "Prepare", "Render", "Present"}));
}

TEST(Scheduler, PhasesRunInOrderWhateverTheRegistrationOrder) {
    Recorder r;
    r.add("present", phases::kPresent);
    r.add("render", phases::kRender);
    r.add("prepare", phases::kPrepare);
    r.add("simulate", phases::kSimulate);
    r.add("startup", phases::kStartup);
    r.scheduler.runAll(r.world);
    EXPECT_EQ(r.ran, (Names{"startup", "simulate", "prepare", "render", "present"}));
}

TEST(Scheduler, WithinAPhaseRegistrationOrder) {
    Recorder r;
    for (const char* n : {"d", "b", "a", "c"}) r.add(n);
    r.scheduler.runAll(r.world);
    EXPECT_EQ(r.ran, (Names{"d", "b", "a", "c"}));
}

TEST(Scheduler, StartupRunsOnceOtherPhasesEveryTime) {
    Recorder r;
    r.add("init", phases::kStartup);
    r.add("step");
    r.scheduler.runAll(r.world);
    r.scheduler.runAll(r.world);
    r.scheduler.runPhase(phases::kStartup, r.world);
    EXPECT_EQ(r.ran, (Names{"init", "step", "step"}));
    r.add("late_init", phases::kStartup);  // added after the first update: runs once, next time
    r.scheduler.runAll(r.world);
    r.scheduler.runAll(r.world);
    EXPECT_EQ(r.ran, (Names{"init", "step", "step", "late_init", "step", "step"}));
}

TEST(Scheduler, ConstraintsPullPrerequisitesAheadAndKeepTheRest) {
    Recorder r;
    r.add("a");
    r.add("b");
    r.add("c");
    r.add("d", phases::kSimulate, {}, {"a"});  // d before a
    EXPECT_EQ(r.scheduler.systemOrder(phases::kSimulate), (Names{"d", "a", "b", "c"}));
    r.add("e", phases::kSimulate, {"c"});  // e after c: already so
    r.add("f", phases::kSimulate, {}, {"b"});
    EXPECT_EQ(r.scheduler.systemOrder(phases::kSimulate), (Names{"d", "a", "f", "b", "c", "e"}));
    r.scheduler.runAll(r.world);
    EXPECT_EQ(r.ran, (Names{"d", "a", "f", "b", "c", "e"}));
}

TEST(Scheduler, ConstraintMayNameALaterRegisteredSystem) {
    Recorder r;
    r.add("render_smoke", phases::kSimulate, {"emit"});
    r.add("emit");
    EXPECT_EQ(r.scheduler.systemOrder(phases::kSimulate), (Names{"emit", "render_smoke"}));
}

TEST(Scheduler, RandomConstraintsAreHonouredAndDeterministic) {
    std::mt19937 rng(77);
    for (int trial = 0; trial < 20; ++trial) {
        const int n = 30;
        // Constraints only from an earlier to a later rank of a hidden permutation: never a cycle.
        std::vector<int> rank(n);
        for (int i = 0; i < n; ++i) rank[i] = i;
        std::shuffle(rank.begin(), rank.end(), rng);
        std::vector<SystemDesc> descs(n);
        std::vector<std::pair<int, int>> mustPrecede;
        for (int i = 0; i < n; ++i) descs[i].name = std::to_string(i).insert(0, 1, 's');
        for (int k = 0; k < 40; ++k) {
            int x = int(rng() % n), y = int(rng() % n);
            if (x == y) continue;
            if (rank[x] > rank[y]) std::swap(x, y);  // x must precede y
            if (rng() % 2)
                descs[y].after.push_back(descs[x].name);
            else
                descs[x].before.push_back(descs[y].name);
            mustPrecede.emplace_back(x, y);
        }
        auto build = [&]() {
            Scheduler s;
            for (const SystemDesc& d : descs) s.addSystem(d, [](World&) {});
            return s.systemOrder(phases::kSimulate);
        };
        const Names order = build();
        ASSERT_EQ(order.size(), std::size_t(n));
        EXPECT_EQ(order, build());  // same input, same order
        auto at = [&](int i) { return std::find(order.begin(), order.end(), descs[i].name) - order.begin(); };
        for (auto [x, y] : mustPrecede) EXPECT_LT(at(x), at(y)) << descs[x].name << " before " << descs[y].name;
    }
}

TEST(Scheduler, CycleIsReportedWithItsMembers) {
    Recorder r;
    r.add("x");
    r.add("a", phases::kSimulate, {"c"});
    r.add("b", phases::kSimulate, {"a"});
    r.add("c", phases::kSimulate, {"b"});
    EXPECT_TRUE(throwsLogicError([&] { r.scheduler.runAll(r.world); }, "cycle"));
    try {
        r.scheduler.resolve();
        FAIL() << "no exception";
    } catch (const std::logic_error& error) {
        const std::string what = error.what();
        for (const char* name : {"'a'", "'b'", "'c'"}) EXPECT_NE(what.find(name), std::string::npos) << what;
        EXPECT_NE(what.find("'a' -> 'b' -> 'c' -> 'a'"), std::string::npos) << what;  // in running order
        EXPECT_NE(what.find("Simulate"), std::string::npos) << what;
    }
    EXPECT_TRUE(r.ran.empty());  // nothing ran with a broken order
}

TEST(Scheduler, SelfConstraintIsACycle) {
    Recorder r;
    r.add("a", phases::kSimulate, {}, {"a"});
    EXPECT_TRUE(throwsLogicError([&] { r.scheduler.resolve(); }, "'a' -> 'a'"));
}

TEST(Scheduler, ConstraintNamingNoSystemIsReported) {
    Recorder r;
    r.add("a", phases::kSimulate, {"ghost"});
    EXPECT_TRUE(throwsLogicError([&] { r.scheduler.resolve(); }, "'ghost'"));
    Recorder q;
    q.add("a", phases::kSimulate, {}, {"phantom"});
    EXPECT_TRUE(throwsLogicError([&] { q.scheduler.runAll(q.world); }, "no system has that name"));
}

TEST(Scheduler, CrossPhaseConstraints) {
    Recorder r;
    r.add("draw", phases::kRender, {"move"});  // agrees with the phase order: fine
    r.add("move", phases::kSimulate, {}, {"draw"});
    r.scheduler.runAll(r.world);
    EXPECT_EQ(r.ran, (Names{"move", "draw"}));
    r.add("bad", phases::kSimulate, {"draw"});  // Simulate can never run after Render
    EXPECT_TRUE(throwsLogicError([&] { r.scheduler.resolve(); }, "later phase 'Render'"));
}

TEST(Scheduler, UnknownPhaseIsReported) {
    Recorder r;
    r.add("a", "Physics");
    EXPECT_TRUE(throwsLogicError([&] { r.scheduler.resolve(); }, "'Physics', which does not exist"));
    r.scheduler.addPhase("Physics", phases::kSimulate);  // the phase may come later
    EXPECT_NO_THROW(r.scheduler.resolve());
}

TEST(Scheduler, SameSystemNameTwiceRunsOnce) {
    Recorder r;
    EXPECT_TRUE(r.add("a"));
    EXPECT_FALSE(r.add("a"));
    EXPECT_FALSE(r.add("a", phases::kRender));
    r.scheduler.runAll(r.world);
    EXPECT_EQ(r.ran, (Names{"a"}));
}

TEST(Scheduler, AddedPhasesTakeTheirPlace) {
    Scheduler s;
    EXPECT_TRUE(s.addPhase("Physics", phases::kSimulate));
    EXPECT_TRUE(s.addPhase("Particles", phases::kSimulate));  // after Physics, which came first
    EXPECT_TRUE(s.addPhase("Collisions", "Physics"));         // after Physics, still before Particles
    EXPECT_TRUE(s.addPhase("Debug", ""));                      // empty: at the end
    EXPECT_TRUE(s.addPhase("Shadows", phases::kPrepare));
    EXPECT_FALSE(s.addPhase("Physics", phases::kRender));      // exists: ignored
    EXPECT_EQ(s.phaseOrder(), (Names{"Startup", "Simulate", "Physics", "Collisions", "Particles", "Prepare",
                                     "Shadows", "Render", "Present", "Debug"}));
    EXPECT_TRUE(throwsLogicError([&] { s.addPhase("X", "Nowhere"); }, "'Nowhere', which does not exist"));
}

TEST(Scheduler, SystemsRunInAddedPhasesAndRunPhaseRunsOne) {
    Recorder r;
    r.scheduler.addPhase("Late", phases::kPresent);
    r.scheduler.addPhase("Warmup", phases::kStartup, PhaseRun::Once);
    r.add("late", "Late");
    r.add("sim");
    r.add("warm", "Warmup");
    r.scheduler.runAll(r.world);
    r.scheduler.runAll(r.world);
    EXPECT_EQ(r.ran, (Names{"warm", "sim", "late", "sim", "late"}));
    r.ran.clear();
    r.scheduler.runPhase("Late", r.world);
    EXPECT_EQ(r.ran, (Names{"late"}));
    EXPECT_TRUE(throwsLogicError([&] { r.scheduler.runPhase("Nope", r.world); }, "'Nope'"));
}

TEST(Scheduler, SystemsSeeTheWorld) {
    Scheduler s;
    World w;
    s.addSystem({.name = "spawn", .phase = phases::kStartup}, [](World& world) { world.create(); });
    s.addSystem({.name = "count"}, [](World& world) { world.insertResource<std::size_t>(world.size()); });
    s.runAll(w);
    EXPECT_EQ(w.resource<std::size_t>(), 1u);
}

TEST(Scheduler, ChangesDuringARunAreRefusedAndAFailingSystemLeavesItUsable) {
    Scheduler s;
    World w;
    int runs = 0;
    s.addSystem({.name = "adder"}, [&](World&) {
        ++runs;
        s.addSystem({.name = "inner"}, [](World&) {});
    });
    EXPECT_TRUE(throwsLogicError([&] { s.runAll(w); }, "while systems run"));
    EXPECT_FALSE(s.hasSystem("inner"));
    Scheduler t;
    bool fail = true;
    t.addSystem({.name = "flaky"}, [&](World&) {
        if (fail) throw std::runtime_error("boom");
    });
    EXPECT_THROW(t.runAll(w), std::runtime_error);
    fail = false;
    EXPECT_NO_THROW(t.runAll(w));
}

TEST(Scheduler, RejectsNamelessOrEmptySystems) {
    Scheduler s;
    EXPECT_THROW(s.addSystem({}, [](World&) {}), std::logic_error);
    EXPECT_THROW(s.addSystem({.name = "x"}, SystemFn{}), std::logic_error);
    EXPECT_FALSE(s.hasSystem("x"));
}

}  // namespace
}  // namespace nimbus::ecs
