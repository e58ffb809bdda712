#include "nimbus/ecs/world.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "expect_error.h"

namespace nimbus::ecs {
namespace {

struct Position {
    double x = 0, y = 0;
};
struct Velocity {
    double dx = 0, dy = 0;
};
struct Tag {};

using test::throwsLogicError;

TEST(World, CreatedEntitiesAreDistinctAndAlive) {
    World w;
    std::set<std::uint32_t> indices;
    for (int i = 0; i < 100; ++i) {
        Entity e = w.create();
        EXPECT_TRUE(w.alive(e));
        indices.insert(e.index);
    }
    EXPECT_EQ(indices.size(), 100u);
    EXPECT_EQ(w.size(), 100u);
    EXPECT_FALSE(w.alive(kNullEntity));
}

TEST(World, StaleHandleIsDetectedAfterIndexReuse) {
    World w;
    const Entity old = w.create();
    w.emplace<Position>(old, 1.0, 2.0);
    w.destroy(old);
    EXPECT_FALSE(w.alive(old));
    const Entity reused = w.create();
    ASSERT_EQ(reused.index, old.index);  // the index is recycled ...
    EXPECT_NE(reused.generation, old.generation);  // ... under a new generation
    EXPECT_TRUE(w.alive(reused));
    EXPECT_FALSE(w.alive(old));
    // The old handle sees nothing of the new entity.
    w.emplace<Position>(reused, 5.0, 6.0);
    EXPECT_FALSE(w.has<Position>(old));
    EXPECT_EQ(w.tryGet<Position>(old), nullptr);
    EXPECT_TRUE(throwsLogicError([&] { (void)w.get<Position>(old); }, "not alive"));
    EXPECT_TRUE(throwsLogicError([&] { (void)w.emplace<Velocity>(old); }, "not alive"));
    EXPECT_TRUE(throwsLogicError([&] { (void)w.remove<Position>(old); }, "not alive"));
    EXPECT_TRUE(throwsLogicError([&] { w.destroy(old); }, "not alive"));
    EXPECT_EQ(w.get<Position>(reused).x, 5.0);
}

TEST(World, StaleAfterManyReuses) {
    World w;
    std::vector<Entity> dead;
    Entity e = w.create();
    for (int i = 0; i < 50; ++i) {
        w.destroy(e);
        dead.push_back(e);
        e = w.create();
    }
    for (Entity d : dead) EXPECT_FALSE(w.alive(d));
    EXPECT_TRUE(w.alive(e));
    EXPECT_EQ(w.size(), 1u);
}

TEST(World, DestroyRemovesAllComponents) {
    World w;
    const Entity a = w.create(), b = w.create();
    w.emplace<Position>(a);
    w.emplace<Velocity>(a);
    w.emplace<Tag>(a);
    w.emplace<Position>(b, 3.0, 4.0);
    w.destroy(a);
    EXPECT_EQ(w.count<Position>(), 1u);
    EXPECT_EQ(w.count<Velocity>(), 0u);
    EXPECT_EQ(w.count<Tag>(), 0u);
    EXPECT_EQ(w.get<Position>(b).y, 4.0);
    const Entity c = w.create();  // takes a's index: must start with no components
    EXPECT_EQ(c.index, a.index);
    EXPECT_FALSE((w.has<Position>(c) || w.has<Velocity>(c) || w.has<Tag>(c)));
}

TEST(World, EmplaceGetReplaceRemove) {
    World w;
    const Entity e = w.create();
    Position& p = w.emplace<Position>(e, 1.0, 2.0);
    EXPECT_EQ(p.x, 1.0);
    EXPECT_EQ(&w.get<Position>(e), &p);
    EXPECT_TRUE(throwsLogicError([&] { (void)w.emplace<Position>(e); }, "already has one"));
    w.replace<Position>(e, 7.0, 8.0);
    EXPECT_EQ(w.get<Position>(e).y, 8.0);
    EXPECT_TRUE(throwsLogicError([&] { (void)w.replace<Velocity>(e, 1.0, 1.0); }, "has none"));
    w.emplaceOrReplace<Velocity>(e, 1.0, 1.0);
    w.emplaceOrReplace<Velocity>(e, 2.0, 3.0);
    EXPECT_EQ(w.get<Velocity>(e).dy, 3.0);
    EXPECT_TRUE((w.has<Position, Velocity>(e)));
    EXPECT_FALSE((w.has<Position, Velocity, Tag>(e)));
    EXPECT_TRUE(w.remove<Velocity>(e));
    EXPECT_FALSE(w.remove<Velocity>(e));
    EXPECT_FALSE(w.remove<Tag>(e));  // a type never stored
    EXPECT_FALSE(w.has<Velocity>(e));
    EXPECT_TRUE(w.alive(e));  // removing its last components does not destroy it
}

TEST(World, MissingComponentErrorNamesTypeAndEntity) {
    World w;
    const Entity e = w.create();
    try {
        (void)w.get<Velocity>(e);
        FAIL() << "no exception";
    } catch (const std::logic_error& error) {
        const std::string what = error.what();
        EXPECT_NE(what.find("Velocity"), std::string::npos) << what;
        EXPECT_NE(what.find(toString(e)), std::string::npos) << what;
    }
    EXPECT_TRUE(throwsLogicError([&] { (void)w.emplace<Tag>(kNullEntity); }, "null entity"));
}

TEST(World, CountsAndForEachEntity) {
    World w;
    std::vector<Entity> es;
    for (int i = 0; i < 10; ++i) es.push_back(w.create());
    for (int i = 0; i < 10; i += 2) w.emplace<Tag>(es[i]);
    EXPECT_EQ(w.count<Tag>(), 5u);
    EXPECT_EQ(w.count<Position>(), 0u);
    w.destroy(es[3]);
    std::vector<Entity> seen;
    w.forEachEntity([&](Entity e) { seen.push_back(e); });
    ASSERT_EQ(seen.size(), 9u);
    for (Entity e : seen) EXPECT_TRUE(w.alive(e));
    EXPECT_EQ(std::find(seen.begin(), seen.end(), es[3]), seen.end());
}

TEST(World, ClearMakesEveryHandleStaleAndKeepsResources) {
    World w;
    std::vector<Entity> es;
    for (int i = 0; i < 5; ++i) {
        es.push_back(w.create());
        w.emplace<Position>(es.back());
    }
    w.destroy(es[1]);
    w.insertResource<int>(42);
    w.clear();
    EXPECT_EQ(w.size(), 0u);
    EXPECT_EQ(w.count<Position>(), 0u);
    for (Entity e : es) EXPECT_FALSE(w.alive(e));
    EXPECT_EQ(w.resource<int>(), 42);
    std::set<Entity, bool (*)(Entity, Entity)> fresh([](Entity a, Entity b) { return a.bits() < b.bits(); });
    for (int i = 0; i < 5; ++i) {
        const Entity e = w.create();
        EXPECT_LT(e.index, 5u);  // indices are reused ...
        for (Entity old : es) EXPECT_NE(e, old);  // ... never handles
        EXPECT_FALSE(w.has<Position>(e));
        fresh.insert(e);
    }
    EXPECT_EQ(fresh.size(), 5u);
}

TEST(World, ComponentReferencesSurviveGrowthOfTheirPool) {
    World w;
    const Entity first = w.create();
    Position& p = w.emplace<Position>(first, 1.0, 1.0);
    for (int i = 0; i < 20000; ++i) w.emplace<Position>(w.create(), double(i), 0.0);
    p.x = 99.0;  // still the same object
    EXPECT_EQ(w.get<Position>(first).x, 99.0);
    EXPECT_EQ(&w.get<Position>(first), &p);
}

TEST(World, ConstAccess) {
    World w;
    const Entity e = w.create();
    w.emplace<Position>(e, 2.0, 3.0);
    const World& cw = w;
    EXPECT_EQ(cw.get<Position>(e).y, 3.0);
    EXPECT_EQ(cw.tryGet<Velocity>(e), nullptr);
    EXPECT_TRUE(cw.has<Position>(e));
    EXPECT_EQ(cw.count<Position>(), 1u);
}

// Components go before resources: a component may own something a resource provides (GL objects
// and their context).
TEST(World, DestroysComponentsBeforeResources) {
    std::vector<std::string> log;
    struct Logs {
        std::vector<std::string>* log;
        std::string name;
        Logs(std::vector<std::string>* l, std::string n) : log(l), name(std::move(n)) {}
        Logs(Logs&& o) noexcept : log(o.log), name(std::move(o.name)) { o.log = nullptr; }
        Logs& operator=(Logs&& o) noexcept {
            log = std::exchange(o.log, nullptr);
            name = std::move(o.name);
            return *this;
        }
        ~Logs() {
            if (log) log->push_back(name);
        }
    };
    {
        World w;
        w.insertResource<Logs>(&log, "resource");
        w.emplace<Logs>(w.create(), &log, "component");
    }
    EXPECT_EQ(log, (std::vector<std::string>{"component", "resource"}));
}

}  // namespace
}  // namespace nimbus::ecs
