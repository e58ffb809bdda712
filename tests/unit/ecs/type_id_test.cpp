#include "nimbus/ecs/type_id.h"

#include <gtest/gtest.h>

#include <string>

namespace nimbus::ecs {
namespace {

struct Alpha {};
struct Beta {};

TEST(TypeId, StableAndDistinctPerType) {
    EXPECT_EQ(typeId<Alpha>(), typeId<Alpha>());
    EXPECT_NE(typeId<Alpha>(), typeId<Beta>());
    EXPECT_NE(typeId<Alpha>(), typeId<int>());
}

TEST(TypeId, IgnoresConstAndReferences) {
    EXPECT_EQ(typeId<const Alpha>(), typeId<Alpha>());
    EXPECT_EQ(typeId<Alpha&>(), typeId<Alpha>());
    EXPECT_EQ(typeId<const Alpha&>(), typeId<Alpha>());
}

TEST(TypeName, IsReadable) {
    EXPECT_NE(std::string(typeName<Alpha>()).find("Alpha"), std::string::npos);
    EXPECT_EQ(std::string(typeName<Alpha>()).find("typeName"), std::string::npos);
    EXPECT_EQ(typeName<int>(), "int");
}

}  // namespace
}  // namespace nimbus::ecs
