// Tests engine/raycast/src/mesh_raycaster.cpp: hits, normals, culling, occlusion, precision.
#include "nimbus/raycast/mesh_raycaster.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "scene_builder.h"

namespace nimbus::raycast {
namespace {

using fixtures::SceneBuilder;
using fixtures::quad;
constexpr double kInf = std::numeric_limits<double>::infinity();

// A 2×2 quad in the plane z = 0 facing +Z, centred on (cx, cy).
assets::Primitive facingZ(double cx = 0.0, double cy = 0.0, int material = -1) {
    return quad({float(cx - 1), float(cy - 1), 0.0f}, {2, 0, 0}, {0, 2, 0}, material);
}

TEST(MeshRaycaster, ClosestHitReportsDistanceNormalsMaterialAndTexcoords) {
    SceneBuilder b;
    const int red = b.addMaterial({1, 0, 0});
    b.addMesh({facingZ(0, 0, red)});
    b.addMesh({facingZ(0, 0, -1)}, {0.0, 0.0, -3.0});  // a second one behind
    const MeshRaycaster rc(b.scene, b.world());
    EXPECT_EQ(rc.triangleCount(), 4u);
    const auto hit = rc.closestHit({0.5, -0.5, 5.0}, {0.0, 0.0, -1.0}, 0.0, kInf);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->distance, 5.0, 1e-6);
    EXPECT_NEAR(hit->position.z, 0.0, 1e-6);
    EXPECT_NEAR(hit->geometricNormal.z, 1.0, 1e-12);
    EXPECT_NEAR(hit->shadingNormal.z, 1.0, 1e-6);
    EXPECT_FALSE(hit->backFace);
    EXPECT_EQ(hit->material, red);
    EXPECT_EQ(hit->node, 0);
    ASSERT_TRUE(hit->hasTexcoord0);
    EXPECT_NEAR(hit->texcoord0.x, 0.75, 1e-6);  // (0.5 + 1) / 2
    EXPECT_NEAR(hit->texcoord0.y, 0.25, 1e-6);
    EXPECT_FALSE(hit->hasTexcoord1);
    // tNear / tFar window: skipping the first quad finds the second; a short ray finds nothing.
    const auto second = rc.closestHit({0.5, -0.5, 5.0}, {0.0, 0.0, -1.0}, 5.5, kInf);
    ASSERT_TRUE(second);
    EXPECT_NEAR(second->distance, 8.0, 1e-6);
    EXPECT_EQ(second->node, 1);
    EXPECT_FALSE(rc.closestHit({0.5, -0.5, 5.0}, {0.0, 0.0, -1.0}, 0.0, 4.9));
    EXPECT_FALSE(rc.closestHit({3.0, 0.0, 5.0}, {0.0, 0.0, -1.0}, 0.0, kInf));  // beside it
}

TEST(MeshRaycaster, BackFacesOfSingleSidedMaterialsAreInvisibleToCameraRaysButBlockShadowRays) {
    SceneBuilder b;
    const int single = b.addMaterial({1, 1, 1}, false);
    const int twoSided = b.addMaterial({1, 1, 1}, true);
    b.addMesh({facingZ(0, 0, single), facingZ(5, 0, twoSided)});
    const MeshRaycaster rc(b.scene, b.world());
    const glm::dvec3 up(0.0, 0.0, 1.0);
    // From behind (below), looking up along +Z.
    EXPECT_FALSE(rc.closestHit({0, 0, -2}, up, 0.0, kInf));
    const auto any = rc.closestHit({0, 0, -2}, up, 0.0, kInf, FaceCulling::None);
    ASSERT_TRUE(any);
    EXPECT_TRUE(any->backFace);
    const auto two = rc.closestHit({5, 0, -2}, up, 0.0, kInf);
    ASSERT_TRUE(two);
    EXPECT_TRUE(two->backFace);
    EXPECT_NEAR(two->distance, 2.0, 1e-6);
    EXPECT_TRUE(rc.occluded({0, 0, -2}, up, kInf));  // every face blocks light
    EXPECT_TRUE(rc.occluded({0, 0, 2}, -up, kInf));
    EXPECT_FALSE(rc.occluded({0, 0, -2}, up, 1.9));  // stops before the face
    EXPECT_FALSE(rc.occluded({0, 0, -2}, -up, kInf));
}

TEST(MeshRaycaster, MirroringTransformsFlipTheFrontFace) {
    SceneBuilder b;
    const int single = b.addMaterial({1, 1, 1}, false);
    assets::Node node;
    node.mesh = 0;
    node.scale = {1.0, 1.0, -1.0};  // negative determinant: glTF makes front faces clockwise
    b.scene.meshes.push_back({"q", {facingZ(0, 0, single)}});
    b.addNode(node);
    const MeshRaycaster rc(b.scene, b.world());
    // The local +Z normal now points to world -Z, and that side is the front.
    EXPECT_FALSE(rc.closestHit({0, 0, 2}, {0, 0, -1}, 0.0, kInf));
    const auto hit = rc.closestHit({0, 0, -2}, {0, 0, 1}, 0.0, kInf);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->geometricNormal.z, -1.0, 1e-12);
    EXPECT_NEAR(hit->shadingNormal.z, -1.0, 1e-6);
    EXPECT_FALSE(hit->backFace);
}

TEST(MeshRaycaster, ShadingNormalsUseTheInverseTranspose) {
    SceneBuilder b;
    assets::Primitive slanted = quad({-1, -1, 0}, {2, 0, 0}, {0, 2, 0});
    const glm::vec3 n = glm::normalize(glm::vec3(1, 0, 1));  // a vertex normal tilted towards +X
    slanted.normals = {n, n, n, n};
    b.scene.meshes.push_back({"s", {slanted}});
    assets::Node node;
    node.mesh = 0;
    node.scale = {4.0, 1.0, 1.0};  // stretch X: the normal must tilt less (inverse transpose)
    b.addNode(node);
    const MeshRaycaster rc(b.scene, b.world());
    const auto hit = rc.closestHit({0, 0, 3}, {0, 0, -1}, 0.0, kInf);
    ASSERT_TRUE(hit);
    const glm::dvec3 expected = glm::normalize(glm::dvec3(0.25, 0.0, 1.0));
    EXPECT_NEAR(hit->shadingNormal.x, expected.x, 1e-6);
    EXPECT_NEAR(hit->shadingNormal.z, expected.z, 1e-6);
}

TEST(MeshRaycaster, NodesOutsideTheSceneAreIgnored) {
    SceneBuilder b;
    b.addMesh({facingZ()});
    b.scene.rootNodes.clear();  // the node exists but no scene root reaches it
    const MeshRaycaster rc(b.scene, b.world());
    EXPECT_TRUE(rc.empty());
    EXPECT_FALSE(rc.closestHit({0, 0, 2}, {0, 0, -1}, 0.0, kInf));
    EXPECT_FALSE(rc.occluded({0, 0, 2}, {0, 0, -1}, kInf));
}

TEST(MeshRaycaster, FarFromTheOriginIsAsPreciseAsAtTheOrigin) {
    const glm::dvec3 shift(1e5, 3e4, -1e5);
    SceneBuilder near, far;
    near.addMesh({fixtures::box({-1, -1, -1}, {1, 1, 1})});
    far.addMesh({fixtures::box({-1, -1, -1}, {1, 1, 1})}, shift);
    const MeshRaycaster a(near.scene, near.world()), c(far.scene, far.world());
    EXPECT_NEAR(glm::length(c.origin() - shift), 0.0, 1e-9);
    for (int i = 0; i < 50; ++i) {
        const glm::dvec3 o(3.0, 0.02 * i - 0.5, 0.013 * i - 0.3);
        const glm::dvec3 d = glm::normalize(glm::dvec3(-1.0, 0.001 * i, -0.002 * i));
        const auto ha = a.closestHit(o, d, 0.0, kInf), hc = c.closestHit(o + shift, d, 0.0, kInf);
        ASSERT_TRUE(ha && hc);
        EXPECT_NEAR(ha->distance, hc->distance, 1e-6);
        // A shadow ray leaving the hit towards the outside never hits its own face, even at 1e5.
        const glm::dvec3 out = ha->geometricNormal;
        EXPECT_FALSE(c.occludedFromSurface(*hc, out, kInf));
        EXPECT_FALSE(a.occludedFromSurface(*ha, out, kInf));
        // ... and one going into the box is blocked by the far side.
        EXPECT_TRUE(c.occludedFromSurface(*hc, -out, kInf));
    }
}

TEST(MeshRaycaster, GrazingShadowRaysDoNotSelfIntersect) {
    SceneBuilder b;
    b.addMesh({quad({-50, 0, -50}, {0, 0, 100}, {100, 0, 0})});  // ground y = 0 facing +Y
    const MeshRaycaster rc(b.scene, b.world());
    int blocked = 0;
    for (int i = 0; i < 200; ++i) {
        const glm::dvec3 o(-40.0 + 0.37 * i, 10.0, -30.0 + 0.29 * i);
        const auto hit = rc.closestHit(o, glm::normalize(glm::dvec3(0.3, -1.0, 0.2)), 0.0, kInf);
        ASSERT_TRUE(hit);
        const glm::dvec3 toLight = glm::normalize(glm::dvec3(1.0, 1e-3, 0.5));  // sun almost at the horizon
        blocked += rc.occludedFromSurface(*hit, toLight, kInf) ? 1 : 0;
    }
    EXPECT_EQ(blocked, 0);
}

}  // namespace
}  // namespace nimbus::raycast
