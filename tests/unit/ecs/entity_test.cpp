#include "nimbus/ecs/entity.h"

#include <gtest/gtest.h>

#include <unordered_set>

namespace nimbus::ecs {
namespace {

TEST(Entity, DefaultIsTheNullEntity) {
    Entity e;
    EXPECT_TRUE(e.isNull());
    EXPECT_EQ(e, kNullEntity);
    EXPECT_TRUE(kNullEntity.isNull());
    EXPECT_FALSE((Entity{0, 0}).isNull());
}

TEST(Entity, EqualityIncludesTheGeneration) {
    EXPECT_EQ((Entity{3, 1}), (Entity{3, 1}));
    EXPECT_NE((Entity{3, 1}), (Entity{3, 2}));
    EXPECT_NE((Entity{3, 1}), (Entity{4, 1}));
}

TEST(Entity, BitsRoundTrip) {
    for (Entity e : {Entity{0, 0}, Entity{7, 9}, Entity{0xFFFFFFFEu, 0xFFFFFFFFu}, kNullEntity}) {
        EXPECT_EQ(Entity::fromBits(e.bits()), e);
    }
    EXPECT_NE((Entity{1, 2}).bits(), (Entity{2, 1}).bits());
}

TEST(Entity, HashesDistinguishGenerations) {
    std::unordered_set<Entity> set{Entity{1, 0}, Entity{1, 1}, Entity{2, 0}};
    EXPECT_EQ(set.size(), 3u);
    EXPECT_TRUE(set.contains(Entity{1, 1}));
    EXPECT_FALSE(set.contains(Entity{1, 2}));
}

TEST(Entity, ToStringNamesIndexAndGeneration) {
    EXPECT_EQ(toString(Entity{12, 3}), "12v3");
    EXPECT_EQ(toString(kNullEntity), "null");
}

}  // namespace
}  // namespace nimbus::ecs
