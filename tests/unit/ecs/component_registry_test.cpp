#include "nimbus/ecs/component_registry.h"

#include <gtest/gtest.h>

#include "expect_error.h"

namespace nimbus::ecs {
namespace {

struct Emitter {
    float rate = 1.0f;
};
struct Medium {
    double extinction = 1.0;
};

TEST(ComponentRegistry, RecordsNameSizeAndType) {
    ComponentRegistry r;
    EXPECT_TRUE(r.add<Emitter>("Emitter"));
    EXPECT_TRUE(r.add<Medium>("Medium"));
    ASSERT_EQ(r.all().size(), 2u);
    EXPECT_EQ(r.all()[0].name, "Emitter");  // registration order
    const ComponentInfo* m = r.find("Medium");
    ASSERT_NE(m, nullptr);
    EXPECT_EQ(m->type, typeId<Medium>());
    EXPECT_EQ(m->size, sizeof(Medium));
    EXPECT_EQ(m->alignment, alignof(Medium));
    EXPECT_EQ(r.find<Emitter>(), &r.all()[0]);
    EXPECT_EQ(r.find("Nothing"), nullptr);
}

TEST(ComponentRegistry, SameRegistrationTwiceIsHarmlessConflictsAreNot) {
    ComponentRegistry r;
    EXPECT_TRUE(r.add<Emitter>("Emitter"));
    EXPECT_FALSE(r.add<Emitter>("Emitter"));
    EXPECT_EQ(r.all().size(), 1u);
    EXPECT_TRUE(test::throwsLogicError([&] { r.add<Emitter>("Spawner"); }, "'Emitter' and 'Spawner'"));
    EXPECT_TRUE(test::throwsLogicError([&] { r.add<Medium>("Emitter"); }, "already names another"));
    EXPECT_THROW(r.add<Medium>(""), std::logic_error);
}

TEST(ComponentRegistry, ErasedOperationsWorkWithoutTheType) {
    ComponentRegistry r;
    r.add<Emitter>("Emitter");
    World w;
    const Entity e = w.create();
    w.emplace<Emitter>(e);
    const ComponentInfo& info = *r.find("Emitter");
    EXPECT_TRUE(info.has(w, e));
    EXPECT_TRUE(info.remove(w, e));
    EXPECT_FALSE(info.has(w, e));
    EXPECT_FALSE(info.remove(w, e));
}

}  // namespace
}  // namespace nimbus::ecs
