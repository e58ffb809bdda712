#include "nimbus/ecs/sparse_set.h"

#include <gtest/gtest.h>

#include <map>
#include <random>
#include <stdexcept>

#include "nimbus/ecs/component_storage.h"

namespace nimbus::ecs {
namespace {

struct Value {
    int v = 0;
};

struct NoDefault {
    explicit NoDefault(int x) : v(x) {}
    int v;
};

struct Tracked {
    static inline int live = 0;
    int v = 0;
    Tracked() { ++live; }
    explicit Tracked(int x) : v(x) { ++live; }
    Tracked(const Tracked& o) : v(o.v) { ++live; }
    Tracked& operator=(const Tracked&) = default;
    ~Tracked() { --live; }
};

TEST(SparseSet, InsertContainsRemove) {
    SparseSet set;
    const Entity a{0, 0}, b{1, 0}, c{2, 0};
    EXPECT_TRUE(set.insert(a));
    EXPECT_TRUE(set.insert(b));
    EXPECT_TRUE(set.insert(c));
    EXPECT_FALSE(set.insert(b));  // already a member
    EXPECT_EQ(set.size(), 3u);
    EXPECT_TRUE(set.contains(b));
    EXPECT_TRUE(set.remove(b));
    EXPECT_FALSE(set.remove(b));
    EXPECT_FALSE(set.contains(b));
    EXPECT_TRUE(set.contains(a));
    EXPECT_TRUE(set.contains(c));
    EXPECT_EQ(set.size(), 2u);
}

TEST(SparseSet, RemoveSwapsTheLastMemberIntoTheHole) {
    SparseSet set;
    for (std::uint32_t i = 0; i < 5; ++i) set.insert(Entity{i * 10, 0});
    ASSERT_TRUE(set.remove(Entity{10, 0}));  // position 1
    ASSERT_EQ(set.size(), 4u);
    EXPECT_EQ(set.at(1), (Entity{40, 0}));   // the last one moved there
    EXPECT_EQ(set.position(Entity{40, 0}), 1u);
    for (std::size_t pos = 0; pos < set.size(); ++pos) EXPECT_EQ(set.position(set.at(pos)), pos);
    ASSERT_TRUE(set.remove(Entity{40, 0}));  // removing the new occupant works too
    ASSERT_TRUE(set.remove(Entity{30, 0}));  // the last position
    EXPECT_EQ(set.size(), 2u);
    EXPECT_TRUE(set.contains(Entity{0, 0}));
    EXPECT_TRUE(set.contains(Entity{20, 0}));
}

TEST(SparseSet, StaleGenerationIsNotAMember) {
    SparseSet set;
    set.insert(Entity{7, 2});
    EXPECT_FALSE(set.contains(Entity{7, 1}));
    EXPECT_FALSE(set.contains(Entity{7, 3}));
    EXPECT_FALSE(set.remove(Entity{7, 1}));
    EXPECT_TRUE(set.contains(Entity{7, 2}));
    EXPECT_THROW(set.insert(Entity{7, 3}), std::logic_error);  // same index, other generation
}

TEST(SparseSet, NullEntityIsNeverAMember) {
    SparseSet set;
    EXPECT_FALSE(set.contains(kNullEntity));
    EXPECT_THROW(set.insert(kNullEntity), std::logic_error);
}

TEST(SparseSet, IndicesOnFarApartPages) {
    SparseSet set;
    const Entity far[] = {Entity{0, 0}, Entity{4095, 0}, Entity{4096, 0}, Entity{1'000'000, 5}, Entity{0xFFFFFFF0u, 1}};
    for (Entity e : far) ASSERT_TRUE(set.insert(e));
    for (Entity e : far) EXPECT_TRUE(set.contains(e));
    EXPECT_FALSE(set.contains(Entity{4097, 0}));
    EXPECT_FALSE(set.contains(Entity{2'000'000, 0}));  // beyond every allocated page
    set.clear();
    EXPECT_TRUE(set.empty());
    for (Entity e : far) EXPECT_FALSE(set.contains(e));
}

TEST(ComponentStorage, RemoveKeepsOtherComponentsIntact) {
    ComponentStorage<Value> s;
    for (std::uint32_t i = 0; i < 6; ++i) s.emplace(Entity{i, 0}, Value{int(i) * 100});
    ASSERT_TRUE(s.remove(Entity{2, 0}));
    ASSERT_TRUE(s.remove(Entity{0, 0}));
    EXPECT_EQ(s.size(), 4u);
    for (std::uint32_t i : {1u, 3u, 4u, 5u}) EXPECT_EQ(s.get(Entity{i, 0}).v, int(i) * 100);
    for (std::size_t pos = 0; pos < s.size(); ++pos)  // components stay parallel to entities
        EXPECT_EQ(s.atPosition(pos).v, int(s.at(pos).index) * 100);
    EXPECT_EQ(s.tryGet(Entity{2, 0}), nullptr);
}

TEST(ComponentStorage, RemovalThroughTheBaseDestroysThePayload) {
    Tracked::live = 0;
    {
        ComponentStorage<Tracked> s;
        SparseSet& base = s;
        s.emplace(Entity{1, 0}, 1);
        s.emplace(Entity{2, 0}, 2);
        EXPECT_TRUE(base.insert(Entity{3, 0}));  // default-constructed component
        EXPECT_EQ(Tracked::live, 3);
        EXPECT_EQ(s.get(Entity{3, 0}).v, 0);
        base.remove(Entity{1, 0});
        EXPECT_EQ(Tracked::live, 2);
        EXPECT_EQ(s.get(Entity{2, 0}).v, 2);
        base.clear();
        EXPECT_EQ(Tracked::live, 0);
        s.emplace(Entity{1, 1}, 7);
    }
    EXPECT_EQ(Tracked::live, 0);
}

TEST(ComponentStorage, InsertWithoutDefaultConstructorThrows) {
    ComponentStorage<NoDefault> s;
    SparseSet& base = s;
    EXPECT_THROW(base.insert(Entity{0, 0}), std::logic_error);
    EXPECT_TRUE(s.empty());
    s.emplace(Entity{0, 0}, 3);
    EXPECT_EQ(s.get(Entity{0, 0}).v, 3);
}

TEST(ComponentStorage, MatchesAMapUnderRandomOperations) {
    std::mt19937 rng(1234);
    ComponentStorage<Value> s;
    std::map<std::uint32_t, int> model;
    for (int step = 0; step < 20000; ++step) {
        const std::uint32_t index = std::uniform_int_distribution<std::uint32_t>(0, 300)(rng) * 37;  // spans pages
        const Entity e{index, 0};
        if (rng() % 3 != 0) {
            if (!model.contains(index)) {
                s.emplace(e, Value{step});
                model[index] = step;
            }
        } else {
            EXPECT_EQ(s.remove(e), model.erase(index) == 1);
        }
    }
    ASSERT_EQ(s.size(), model.size());
    for (const auto& [index, v] : model) ASSERT_EQ(s.get(Entity{index, 0}).v, v);
    for (std::size_t pos = 0; pos < s.size(); ++pos) ASSERT_EQ(s.position(s.at(pos)), pos);
}

}  // namespace
}  // namespace nimbus::ecs
