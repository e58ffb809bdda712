// World transforms (hierarchy, precision far from the origin), bounds, camera and light
// resolution.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <glm/gtc/quaternion.hpp>

#include "asset_test_util.h"
#include "nimbus/assets/scene_queries.h"

namespace nimbus::assets {
namespace {

using test::dataPath;

void expectNear(const glm::dvec3& a, const glm::dvec3& b, double eps = 1e-9) {
    EXPECT_NEAR(a.x, b.x, eps);
    EXPECT_NEAR(a.y, b.y, eps);
    EXPECT_NEAR(a.z, b.z, eps);
}

Scene parentAndChild() {
    Scene s;
    s.nodes.resize(2);
    s.nodes[0].translation = {1, 0, 0};
    s.nodes[0].rotation = glm::angleAxis(std::numbers::pi / 2, glm::dvec3(0, 0, 1));
    s.nodes[0].scale = {2, 2, 2};
    s.nodes[0].children = {1};
    s.nodes[1].parent = 0;
    s.nodes[1].translation = {1, 0, 0};
    s.rootNodes = {0};
    return s;
}

TEST(SceneQueries, WorldTransformsComposeParentTimesChild) {
    const std::vector<glm::dmat4> world = computeWorldTransforms(parentAndChild(), 0.0);
    ASSERT_EQ(world.size(), 2u);
    expectNear(glm::dvec3(world[0][3]), {1, 0, 0});
    // The child's (1,0,0) is scaled by 2 and turned 90 degrees about Z, then moved by (1,0,0).
    expectNear(glm::dvec3(world[1][3]), {1, 2, 0});
    expectNear(glm::dvec3(world[1][0]), {0, 2, 0});
}

TEST(SceneQueries, ChildrenListedBeforeTheirParentStillCompose) {
    Scene s;
    s.nodes.resize(3);
    s.nodes[2].children = {0};
    s.nodes[2].translation = {0, 0, 5};
    s.nodes[0].children = {1};
    s.nodes[0].translation = {0, 1, 0};
    s.nodes[1].translation = {1, 0, 0};
    s.rootNodes = {2};
    const auto world = computeWorldTransforms(s, 0.0);
    expectNear(glm::dvec3(world[1][3]), {1, 1, 5});
}

TEST(SceneQueries, WorldTransformsKeepPrecisionFarFromTheOrigin) {
    Scene s;
    s.nodes.resize(2);
    s.nodes[0].translation = {1e5 + 0.25, -3e5, 7e5};
    s.nodes[0].children = {1};
    s.nodes[1].translation = {1e-4, 2e-4, 3e-4};
    const auto world = computeWorldTransforms(s, 0.0);
    const glm::dvec3 offset = glm::dvec3(world[1][3]) - glm::dvec3(world[0][3]);
    expectNear(offset, {1e-4, 2e-4, 3e-4}, 1e-10);  // float would lose this entirely at 1e5
}

TEST(SceneQueries, MatrixNodesAreUsedAsGiven) {
    const Scene box = loadScene(dataPath("khronos/Box/Box.gltf"));
    const auto world = computeWorldTransforms(box, 0.0);
    EXPECT_EQ(world[0], box.nodes[0].matrix);
    EXPECT_EQ(localTransform(box.nodes[0]), box.nodes[0].matrix);
    const Aabb bounds = meshBounds(box, world);
    ASSERT_FALSE(bounds.empty());
    expectNear(bounds.min, glm::dvec3(-0.5));
    expectNear(bounds.max, glm::dvec3(0.5));
}

TEST(SceneQueries, MeshBoundsFollowTransformsAndSkipNodesOutsideTheScene) {
    Scene s = loadScene(dataPath("scenes/primitives.gltf"));
    const Aabb all = meshBounds(s, computeWorldTransforms(s, 0.0));
    EXPECT_EQ(all.max.x, 14.0);  // the sparse mesh's (4, 0, 0) moved by its node's (10, 0, 0)
    EXPECT_EQ(all.max.z, 7.0);
    s.rootNodes = {0};
    const Aabb first = meshBounds(s, computeWorldTransforms(s, 0.0));
    EXPECT_EQ(first.max, glm::dvec3(5.0));  // the degenerate triangle at (5, 5, 5)
    EXPECT_EQ(first.min, glm::dvec3(-1.0, 0.0, 0.0));  // the fan's (-1, 1, 0)
    EXPECT_EQ(nodesInScene(s), (std::vector<bool>{true, false}));
    s.rootNodes.clear();
    EXPECT_TRUE(meshBounds(s, computeWorldTransforms(s, 0.0)).empty());
}

TEST(SceneQueries, FirstCameraIsTheLowestNodeIndexInTheScene) {
    const Scene s = loadScene(dataPath("scenes/lights_cameras.gltf"));
    const auto world = computeWorldTransforms(s, 0.0);
    const ResolvedCamera cam = resolveCamera(s, world, "", meshBounds(s, world), 1.0);
    EXPECT_FALSE(cam.synthesized);
    EXPECT_EQ(cam.name, "WideCam");
    EXPECT_EQ(cam.params.yfov, 1.0);
    expectNear(cam.position(), {0, 2, 10});
    expectNear(cam.forward(), {0, 0, -1});
    expectNear(cam.up(), {0, 1, 0});
    expectNear(cam.right(), {1, 0, 0});
}

TEST(SceneQueries, CameraIsFoundByCameraNameOrNodeName) {
    const Scene s = loadScene(dataPath("scenes/lights_cameras.gltf"));
    const auto world = computeWorldTransforms(s, 0.0);
    for (const char* name : {"TopCam", "Top"}) {
        SCOPED_TRACE(name);
        const ResolvedCamera cam = resolveCamera(s, world, name, Aabb{}, 1.0);
        EXPECT_EQ(cam.name, "TopCam");
        EXPECT_EQ(cam.params.projection, Projection::Orthographic);
        expectNear(cam.position(), {0, 10, 0});
        expectNear(cam.forward(), {0, -1, 0});  // -90 degrees about X turns -Z into -Y
        expectNear(cam.up(), {0, 0, -1});
        expectNear(cam.right(), {1, 0, 0});
    }
}

TEST(SceneQueries, UnknownCameraNameIsRefusedListingTheCameras) {
    const Scene s = loadScene(dataPath("scenes/lights_cameras.gltf"));
    const auto world = computeWorldTransforms(s, 0.0);
    try {
        resolveCamera(s, world, "Nope", Aabb{}, 1.0);
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("camera \"Nope\""), std::string::npos) << m;
        EXPECT_NE(m.find("0 \"WideCam\", 1 \"TopCam\""), std::string::npos) << m;
        EXPECT_TRUE(test::isOneLine(m));
    }
}

TEST(SceneQueries, CameraIsFoundByIndexAndUnnamedOnesAreListedByIndex) {
    // Khronos Cameras.gltf: two unnamed cameras at one place, cameras[1] orthographic.
    const Scene s = loadScene(dataPath("khronos/Cameras/Cameras.gltf"));
    const auto world = computeWorldTransforms(s, 0.0);
    EXPECT_EQ(resolveCamera(s, world, "", Aabb{}, 1.0).params.projection, Projection::Perspective);
    const ResolvedCamera ortho = resolveCamera(s, world, "1", Aabb{}, 1.0);
    EXPECT_EQ(ortho.params.projection, Projection::Orthographic);
    EXPECT_EQ(ortho.name, "camera 1");
    EXPECT_EQ(resolveCamera(s, world, "0", Aabb{}, 1.0).params.projection, Projection::Perspective);
    try {
        resolveCamera(s, world, "2", Aabb{}, 1.0);
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("Cameras.gltf"), std::string::npos) << m;
        EXPECT_NE(m.find("0 (unnamed), 1 (unnamed)"), std::string::npos) << m;
        EXPECT_TRUE(test::isOneLine(m));
    }
}

TEST(SceneQueries, CameraAxesAreUnitUnderNonUniformScale) {
    Scene s;
    s.nodes.resize(1);
    s.nodes[0].camera = 0;
    s.nodes[0].scale = {3, 0.5, 7};
    s.nodes[0].rotation = glm::angleAxis(0.3, glm::normalize(glm::dvec3(1, 2, 3)));
    s.cameras.resize(1);
    s.rootNodes = {0};
    const auto world = computeWorldTransforms(s, 0.0);
    const ResolvedCamera cam = resolveCamera(s, world, "", Aabb{}, 1.0);
    EXPECT_NEAR(glm::length(cam.forward()), 1.0, 1e-12);
    EXPECT_NEAR(glm::length(cam.up()), 1.0, 1e-12);
    EXPECT_NEAR(glm::dot(cam.forward(), cam.up()), 0.0, 1e-12);
    expectNear(cam.right(), glm::cross(cam.forward(), cam.up()), 1e-12);
    expectNear(cam.forward(), -glm::normalize(glm::dvec3(world[0][2])), 1e-12);
}

TEST(SceneQueries, SceneWithoutCameraGetsOneFramingTheBounds) {
    const Scene box = loadScene(dataPath("khronos/Box/Box.gltf"));
    const auto world = computeWorldTransforms(box, 0.0);
    Aabb frame = meshBounds(box, world);
    frame.extend(glm::dvec3(3, 0.5, 0.5));  // something else visible, e.g. a medium
    for (double aspect : {1.0, 0.5, 2.0}) {
        SCOPED_TRACE(aspect);
        const ResolvedCamera cam = resolveCamera(box, world, "", frame, aspect);
        EXPECT_TRUE(cam.synthesized);
        EXPECT_EQ(cam.params.projection, Projection::Perspective);
        EXPECT_EQ(cam.params.yfov, 0.8);
        expectNear(cam.forward(), glm::normalize(frame.center() - cam.position()), 1e-9);
        expectNear(glm::normalize(cam.position() - frame.center()), glm::normalize(glm::dvec3(1, 0.6, 1.4)), 1e-9);
        // Every corner of the frame projects inside the image and between the clip planes.
        const double tanHalfV = std::tan(0.5 * cam.params.yfov);
        for (int c = 0; c < 8; ++c) {
            const glm::dvec3 p((c & 1) ? frame.max.x : frame.min.x, (c & 2) ? frame.max.y : frame.min.y, (c & 4) ? frame.max.z : frame.min.z);
            const glm::dvec3 d = p - cam.position();
            const double z = glm::dot(d, cam.forward());
            EXPECT_GT(z, cam.params.znear);
            EXPECT_LT(z, cam.params.zfar);
            EXPECT_LE(std::abs(glm::dot(d, cam.up())) / z, tanHalfV);
            EXPECT_LE(std::abs(glm::dot(d, cam.right())) / z, tanHalfV * aspect);
        }
    }
}

TEST(SceneQueries, EmptySceneStillGetsAFiniteCamera) {
    const Scene empty;
    const ResolvedCamera cam = resolveCamera(empty, {}, "", Aabb{}, 1.0);
    EXPECT_TRUE(cam.synthesized);
    EXPECT_TRUE(std::isfinite(cam.position().x) && std::isfinite(cam.forward().y));
    EXPECT_GT(cam.params.znear, 0.0);
}

TEST(SceneQueries, LightsArePlacedByTheirNodes) {
    const Scene s = loadScene(dataPath("scenes/lights_cameras.gltf"));
    const auto lights = resolveLights(s, computeWorldTransforms(s, 0.0));
    ASSERT_EQ(lights.size(), 3u);  // the node outside the default scene is not a light
    EXPECT_EQ(lights[0].name, "Sun");
    EXPECT_FALSE(lights[0].synthesized);
    expectNear(lights[0].direction, {0, -1, 0});
    EXPECT_EQ(lights[1].name, "Bulb");
    expectNear(lights[1].position, {1, 2, 3});
    EXPECT_EQ(lights[2].name, "SpotNode");  // an unnamed light takes its node's name
    EXPECT_EQ(lights[2].params.type, LightType::Spot);
    expectNear(lights[2].position, {0, 5, 0});
    expectNear(lights[2].direction, {0, -1, 0});  // unit despite the node's scale of 2
}

TEST(SceneQueries, SceneWithoutLightsGetsTheDefaultSun) {
    const Scene box = loadScene(dataPath("khronos/Box/Box.gltf"));
    const auto lights = resolveLights(box, computeWorldTransforms(box, 0.0));
    ASSERT_EQ(lights.size(), 1u);
    EXPECT_TRUE(lights[0].synthesized);
    EXPECT_EQ(lights[0].params.type, LightType::Directional);
    EXPECT_EQ(lights[0].params.intensity, 3.0f);
    EXPECT_EQ(lights[0].params.color, glm::vec3(1.0f));
    expectNear(lights[0].direction, glm::normalize(glm::dvec3(-0.4, -1.0, -0.3)));
}

}  // namespace
}  // namespace nimbus::assets
