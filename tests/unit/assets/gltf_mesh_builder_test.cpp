// Primitives become indexed triangle lists: strips and fans expanded with glTF's winding, points
// and lines dropped, flat normals (unwelded) when the file has none, never NaN for degenerate
// triangles; sparse positions substituted.
#include <gtest/gtest.h>

#include <cmath>

#include "asset_test_util.h"
#include "nimbus/assets/scene.h"

namespace nimbus::assets {
namespace {

class MeshBuilding : public ::testing::Test {
protected:
    static void SetUpTestSuite() { scene_ = new Scene(loadScene(test::dataPath("scenes/primitives.gltf"))); }
    static void TearDownTestSuite() {
        delete scene_;
        scene_ = nullptr;
    }
    static const Primitive& prim(std::size_t mesh, std::size_t p) { return scene_->meshes.at(mesh).primitives.at(p); }
    static Scene* scene_;
};
Scene* MeshBuilding::scene_ = nullptr;

void expectSequential(const std::vector<std::uint32_t>& indices) {
    for (std::size_t i = 0; i < indices.size(); ++i) EXPECT_EQ(indices[i], i);
}

TEST_F(MeshBuilding, PointsAndLinesAreDropped) {
    ASSERT_EQ(scene_->meshes.size(), 2u);
    EXPECT_EQ(scene_->meshes[0].name, "Primitives");
    EXPECT_EQ(scene_->meshes[0].primitives.size(), 4u);  // strip, fan, degenerate, indexed; not POINTS / LINES
}

TEST_F(MeshBuilding, StripIsExpandedWithAlternatingWindingAndFlatNormals) {
    const Primitive& p = prim(0, 0);
    ASSERT_EQ(p.indices.size(), 6u);
    expectSequential(p.indices);  // unwelded: one vertex per corner
    ASSERT_EQ(p.positions.size(), 6u);
    EXPECT_EQ(p.positions[3], glm::vec3(1, 0, 0));  // second triangle: v1, v3, v2
    EXPECT_EQ(p.positions[4], glm::vec3(1, 1, 0));
    EXPECT_EQ(p.positions[5], glm::vec3(0, 1, 0));
    for (const glm::vec3& n : p.normals) EXPECT_EQ(n, glm::vec3(0, 0, 1));
    EXPECT_EQ(p.material, -1);
    EXPECT_EQ(p.boundsMin, glm::vec3(0, 0, 0));
    EXPECT_EQ(p.boundsMax, glm::vec3(1, 1, 0));
}

TEST_F(MeshBuilding, FanIsExpandedAroundItsFirstVertex) {
    const Primitive& p = prim(0, 1);
    ASSERT_EQ(p.indices.size(), 9u);  // 5 fan vertices: 3 triangles
    EXPECT_EQ(p.positions[0], glm::vec3(1, 0, 0));  // glTF: {v(i+1), v(i+2), v0}
    EXPECT_EQ(p.positions[1], glm::vec3(1, 1, 0));
    EXPECT_EQ(p.positions[2], glm::vec3(0, 0, 0));
    EXPECT_EQ(p.positions[8], glm::vec3(0, 0, 0));
    for (const glm::vec3& n : p.normals) EXPECT_EQ(n, glm::vec3(0, 0, 1));
}

TEST_F(MeshBuilding, DegenerateTrianglesGetFiniteUnitNormals) {
    const Primitive& p = prim(0, 2);
    ASSERT_EQ(p.normals.size(), 6u);
    for (const glm::vec3& n : p.normals) {
        EXPECT_TRUE(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z));
        EXPECT_NEAR(glm::length(n), 1.0f, 1e-6f);
    }
    EXPECT_NEAR(p.normals[0].x, 0.0f, 1e-6f);  // collinear along X: perpendicular to the edge
    EXPECT_EQ(p.normals[3], glm::vec3(0, 1, 0));  // three equal points: +Y
}

TEST_F(MeshBuilding, GivenNormalsAreKeptNormalizedWithIndicesAndTexcoords) {
    const Primitive& p = prim(0, 3);
    EXPECT_EQ(p.indices, (std::vector<std::uint32_t>{0, 1, 2}));
    ASSERT_EQ(p.positions.size(), 3u);
    for (const glm::vec3& n : p.normals) EXPECT_EQ(n, glm::vec3(0, 0, 1));
    ASSERT_EQ(p.texcoords0.size(), 3u);  // normalized UNSIGNED_BYTE
    EXPECT_EQ(p.texcoords0[1], glm::vec2(1, 0));
    EXPECT_NEAR(p.texcoords0[2].y, 0.2f, 1e-6f);
    EXPECT_TRUE(p.texcoords1.empty());
    EXPECT_EQ(p.material, 0);
    EXPECT_EQ(p.boundsMax, glm::vec3(2, 3, 0));
    ASSERT_EQ(scene_->materials.size(), 1u);
    EXPECT_TRUE(scene_->materials[0].doubleSided);
    EXPECT_EQ(scene_->materials[0].baseColorFactor, glm::vec4(1, 0, 0, 1));
}

TEST_F(MeshBuilding, SparsePositionsAreSubstituted) {
    EXPECT_EQ(prim(1, 0).positions[0], glm::vec3(0, 0, 0));  // unwelded, but the corners are v0, v1, v2
    EXPECT_EQ(prim(1, 0).positions[2], glm::vec3(0, 1, 7));
    EXPECT_EQ(prim(1, 0).boundsMax.z, 7.0f);
    // No buffer view: zeros, then the sparse values.
    EXPECT_EQ(prim(1, 1).positions[0], glm::vec3(0, 0, 0));
    EXPECT_EQ(prim(1, 1).positions[1], glm::vec3(4, 0, 0));
    EXPECT_EQ(prim(1, 1).positions[2], glm::vec3(0, 4, 0));
}

}  // namespace
}  // namespace nimbus::assets
