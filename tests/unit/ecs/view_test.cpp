#include "nimbus/ecs/view.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <optional>
#include <random>
#include <set>
#include <type_traits>
#include <vector>

#include "nimbus/ecs/world.h"

namespace nimbus::ecs {
namespace {

struct A {
    int v = 0;
};
struct B {
    int v = 0;
};
struct C {
    int v = 0;
};

bool byBits(Entity x, Entity y) { return x.bits() < y.bits(); }
using EntitySet = std::set<Entity, decltype(&byBits)>;
EntitySet makeSet() { return EntitySet(&byBits); }

TEST(View, VisitsExactlyTheEntitiesWithEveryComponent) {
    World w;
    std::vector<Entity> es;
    for (int i = 0; i < 8; ++i) es.push_back(w.create());
    for (int i : {0, 1, 2, 3, 4}) w.emplace<A>(es[i], i);
    for (int i : {1, 3, 5, 7}) w.emplace<B>(es[i], 10 * i);
    EntitySet seen = makeSet();
    w.view<A, B>().each([&](Entity e, A& a, B& b) {
        EXPECT_TRUE(seen.insert(e).second);  // once each
        EXPECT_EQ(b.v, 10 * a.v);
    });
    EXPECT_EQ(seen, (EntitySet({es[1], es[3]}, &byBits)));
}

TEST(View, RangeForYieldsEntityAndComponents) {
    World w;
    for (int i = 0; i < 20; ++i) {
        const Entity e = w.create();
        w.emplace<A>(e, i);
        if (i % 4 == 0) w.emplace<B>(e, i);
    }
    int visits = 0;
    for (auto [e, a, b] : w.view<A, B>()) {
        static_assert(std::is_same_v<decltype(a), A&>);
        EXPECT_EQ(a.v, b.v);
        EXPECT_EQ(&a, &w.get<A>(e));
        a.v += 1000;  // writes go to the stored component
        ++visits;
    }
    EXPECT_EQ(visits, 5);
    int written = 0;
    w.view<A>().each([&](A& a) { written += a.v >= 1000; });  // the form without the entity
    EXPECT_EQ(written, 5);
    auto v = w.view<A, B>();
    EXPECT_EQ(std::distance(v.begin(), v.end()), 5);
}

TEST(View, ConstViewsGiveReadOnlyAccess) {
    World w;
    const Entity e = w.create();
    w.emplace<A>(e, 1);
    w.emplace<B>(e, 2);
    const World& cw = w;
    int sum = 0;
    cw.view<A, B>().each([&](Entity, const A& a, const B& b) { sum += a.v + b.v; });
    EXPECT_EQ(sum, 3);
    for (auto [entity, a, b] : cw.view<A, B>()) {
        static_assert(std::is_same_v<decltype(a), const A&>);
        static_assert(std::is_same_v<decltype(b), const B&>);
        EXPECT_EQ(entity, e);
    }
    // Mixed: read A, write B.
    for (auto [entity, a, b] : w.view<const A, B>()) {
        static_assert(std::is_same_v<decltype(a), const A&>);
        static_assert(std::is_same_v<decltype(b), B&>);
        b.v = a.v * 10;
    }
    EXPECT_EQ(w.get<B>(e).v, 10);
    EXPECT_EQ(cw.view<C>().begin(), cw.view<C>().end());  // a type never stored: empty, no pool made
}

TEST(View, DrivesFromTheSmallestPool) {
    World w;
    for (int i = 0; i < 100; ++i) {
        const Entity e = w.create();
        w.emplace<A>(e);
        if (i < 3) w.emplace<B>(e);
    }
    auto v = w.view<A, B>();
    EXPECT_EQ(v.sizeHint(), 3u);
    const Entity outsider = w.create();
    w.emplace<A>(outsider);
    EXPECT_FALSE(v.contains(outsider));
    EXPECT_EQ((w.view<A, C>().sizeHint()), 0u);
}

TEST(View, RemovingTheCurrentEntitysComponentsIsSafe) {
    World w;
    for (int i = 0; i < 1000; ++i) {
        const Entity e = w.create();
        w.emplace<A>(e, i);
        w.emplace<B>(e, i);
    }
    std::vector<int> seen;
    w.view<A, B>().each([&](Entity e, A& a, B&) {
        seen.push_back(a.v);
        w.remove<A>(e);  // shrinks a pool under the loop
    });
    std::sort(seen.begin(), seen.end());
    ASSERT_EQ(seen.size(), 1000u);
    for (int i = 0; i < 1000; ++i) ASSERT_EQ(seen[i], i);  // every entity exactly once
    EXPECT_EQ(w.count<A>(), 0u);
    EXPECT_EQ(w.count<B>(), 1000u);
}

TEST(View, DestroyingTheCurrentEntityInRangeForIsSafe) {
    World w;
    for (int i = 0; i < 500; ++i) {
        const Entity e = w.create();
        w.emplace<A>(e, i);
        if (i % 2 == 0) w.emplace<B>(e, i);
    }
    std::set<int> seen;
    for (auto [e, a, b] : w.view<A, B>()) {
        EXPECT_TRUE(seen.insert(a.v).second);
        w.destroy(e);
    }
    EXPECT_EQ(seen.size(), 250u);
    EXPECT_EQ(w.size(), 250u);
    EXPECT_EQ(w.count<B>(), 0u);
}

TEST(View, EmplacingDuringIterationKeepsReferencesValid) {
    World w;
    for (int i = 0; i < 10; ++i) w.emplace<A>(w.create(), i);
    int visited = 0;
    w.view<A>().each([&](A& a) {
        ++visited;
        for (int k = 0; k < 1000; ++k) w.emplace<A>(w.create(), -1);  // same pool grows a lot
        a.v += 100;  // the reference is still good
    });
    EXPECT_EQ(visited, 10);  // entities added during the loop are not visited
    int bumped = 0;
    w.view<const A>().each([&](const A& a) { bumped += a.v >= 100; });
    EXPECT_EQ(bumped, 10);
}

// The view against a brute-force model, under a long random mix of operations.
TEST(View, MatchesBruteForceUnderRandomOperations) {
    struct Row {
        std::optional<int> a, b, c;
    };
    std::mt19937 rng(20240607);
    World w;
    std::map<std::uint64_t, std::pair<Entity, Row>> model;  // by Entity::bits
    std::vector<Entity> live;

    auto pick = [&]() { return live[std::uniform_int_distribution<std::size_t>(0, live.size() - 1)(rng)]; };
    auto check = [&]() {
        auto expectView = [&](auto view, auto wants) {
            EntitySet expected = makeSet(), fromEach = makeSet(), fromRange = makeSet();
            for (const auto& [bits, entry] : model)
                if (wants(entry.second)) expected.insert(entry.first);
            auto expectValue = [](Entity e, int v) { EXPECT_EQ(v, static_cast<int>(e.index) * 7 + 1); };
            view.each([&](Entity e, auto&... comps) {
                EXPECT_TRUE(fromEach.insert(e).second);
                (expectValue(e, comps.v), ...);
            });
            for (auto element : view) EXPECT_TRUE(fromRange.insert(std::get<0>(element)).second);
            EXPECT_EQ(fromEach, expected);
            EXPECT_EQ(fromRange, expected);
        };
        expectView(w.view<A>(), [](const Row& r) { return r.a.has_value(); });
        expectView(w.view<A, B>(), [](const Row& r) { return r.a && r.b; });
        expectView(w.view<B, C>(), [](const Row& r) { return r.b && r.c; });
        expectView(w.view<A, B, C>(), [](const Row& r) { return r.a && r.b && r.c; });
        expectView(static_cast<const World&>(w).view<C, A>(), [](const Row& r) { return r.c && r.a; });
    };

    for (int step = 0; step < 4000; ++step) {
        const unsigned op = rng() % 10;
        if (live.empty() || op < 3) {
            const Entity e = w.create();
            live.push_back(e);
            model[e.bits()] = {e, Row{}};
        } else if (op < 4) {
            const Entity e = pick();
            w.destroy(e);
            model.erase(e.bits());
            live.erase(std::find(live.begin(), live.end(), e));
        } else {
            // Every component value is index*7+1, so a value that moved to the wrong entity shows.
            const Entity e = pick();
            Row& row = model.at(e.bits()).second;
            const int value = static_cast<int>(e.index) * 7 + 1;
            const bool add = rng() % 3 != 0;
            auto toggle = [&](auto tag, std::optional<int>& slot) {
                using T = decltype(tag);
                if (!add) {
                    EXPECT_EQ(w.remove<T>(e), slot.has_value());
                    slot.reset();
                } else if (!slot) {
                    w.emplace<T>(e, value);
                    slot = value;
                }
            };
            switch (rng() % 3) {
                case 0: toggle(A{}, row.a); break;
                case 1: toggle(B{}, row.b); break;
                default: toggle(C{}, row.c); break;
            }
        }
        if (step % 200 == 199) check();
        if (::testing::Test::HasFailure()) return;
    }
    check();
}

}  // namespace
}  // namespace nimbus::ecs
