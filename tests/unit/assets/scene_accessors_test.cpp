// readFloatAccessor / accessorCount: what a plugin may read after loading, and what is refused.
#include <gtest/gtest.h>

#include "asset_test_util.h"

namespace nimbus::assets {
namespace {

// Accessor order in scenes/primitives.gltf (generate_test_data.py): 0 strip positions (4 VEC3),
// 2 fan indices, 8 normalized UNSIGNED_BYTE texcoords, 10 sparse positions.
class AccessorReads : public ::testing::Test {
protected:
    static void SetUpTestSuite() { scene_ = new Scene(loadScene(test::dataPath("scenes/primitives.gltf"))); }
    static void TearDownTestSuite() {
        delete scene_;
        scene_ = nullptr;
    }
    static std::string refusal(int accessor, int components) {
        try {
            readFloatAccessor(*scene_, accessor, components, "node \"Cloud\" (nodes[3])", "particles.position");
        } catch (const InputError& e) {
            return e.what();
        }
        ADD_FAILURE() << "accessor " << accessor << " was read";
        return {};
    }
    static Scene* scene_;
};
Scene* AccessorReads::scene_ = nullptr;

TEST_F(AccessorReads, FloatVec3IsRead) {
    const std::vector<float> v = readFloatAccessor(*scene_, 0, 3, "node", "field");
    EXPECT_EQ(v, (std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0}));
    EXPECT_EQ(accessorCount(*scene_, 0, "node", "field"), 4u);
}

TEST_F(AccessorReads, WrongTypeIsRefusedNamingTheReference) {
    const std::string m = refusal(0, 1);
    EXPECT_EQ(m.rfind(scene_->displayName() + ": node \"Cloud\" (nodes[3]): particles.position: ", 0), 0u) << m;
    EXPECT_NE(m.find("VEC3 FLOAT, expected SCALAR FLOAT"), std::string::npos) << m;
    EXPECT_NE(refusal(2, 1).find("UNSIGNED_SHORT"), std::string::npos);
    EXPECT_NE(refusal(8, 2).find("UNSIGNED_BYTE"), std::string::npos);
}

TEST_F(AccessorReads, OutOfRangeAndSparseAreRefused) {
    EXPECT_NE(refusal(99, 3).find("accessor index 99 is out of range"), std::string::npos);
    EXPECT_NE(refusal(-1, 3).find("out of range"), std::string::npos);
    EXPECT_NE(refusal(10, 3).find("sparse"), std::string::npos);
    EXPECT_THROW(accessorCount(*scene_, 99, "o", "f"), InputError);
}

}  // namespace
}  // namespace nimbus::assets
