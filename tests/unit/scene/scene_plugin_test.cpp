// ScenePlugin (scene/scene_plugin.h): spawnScene makes one entity per node with the components the
// node carries, a failing spawner leaves nothing of the scene behind, and simulateTo advances the
// fixed-step clock to round(T/dt) steps with every animated node posed as computeWorldTransforms says.
#include "nimbus/scene/scene_plugin.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <memory>
#include <string>

#include <glm/gtc/quaternion.hpp>

#include "nimbus/base/error.h"
#include "nimbus/ecs/app.h"

namespace nimbus::scene {
namespace {

assets::Primitive triangle() {
    assets::Primitive p;
    p.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    p.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
    p.indices = {0, 1, 2};
    p.boundsMax = {1, 1, 0};
    return p;
}

// Nodes: 0 "root" (animated rotation) → child 1 "blade" (mesh); 2 "eye" (camera); 3 "sun" (light);
// 4 "mover" (mesh, animated translation); 5 "orphan" (mesh, in no scene).
std::shared_ptr<const assets::Scene> makeScene() {
    auto s = std::make_shared<assets::Scene>();
    s->meshes.push_back({"tri", {triangle()}});
    assets::Camera camera;
    camera.name = "eye_camera";
    camera.yfov = 0.6;
    s->cameras.push_back(camera);
    assets::Light light;
    light.name = "sun_light";
    light.type = assets::LightType::Spot;
    light.intensity = 7.0f;
    s->lights.push_back(light);

    assets::Node root;
    root.name = "root";
    root.translation = {1.0e5, 2.0, 3.0};
    root.children = {1};
    assets::Node blade;
    blade.name = "blade";
    blade.parent = 0;
    blade.translation = {0.0, 0.0, 2.0};
    blade.mesh = 0;
    assets::Node eye;
    eye.name = "eye";
    eye.camera = 0;
    eye.translation = {0, 1, 10};
    assets::Node sun;
    sun.name = "sun";
    sun.light = 0;
    sun.rotation = glm::angleAxis(-1.0, glm::dvec3(1, 0, 0));
    assets::Node mover;
    mover.name = "mover";
    mover.mesh = 0;
    assets::Node orphan;
    orphan.name = "orphan";
    orphan.mesh = 0;
    s->nodes = {root, blade, eye, sun, mover, orphan};
    s->rootNodes = {0, 2, 3, 4};

    assets::Animation animation;
    animation.name = "all";
    assets::AnimationChannel spin;
    spin.node = 0;
    spin.path = assets::AnimationPath::Rotation;
    spin.times = {0.0f, 2.0f};
    const glm::quat q0(1.0f, 0.0f, 0.0f, 0.0f), q1 = glm::angleAxis(3.0f, glm::vec3(0, 1, 0));
    spin.values = {{q0.x, q0.y, q0.z, q0.w}, {q1.x, q1.y, q1.z, q1.w}};
    assets::AnimationChannel move;
    move.node = 4;
    move.path = assets::AnimationPath::Translation;
    move.times = {0.0f, 1.0f, 2.0f};
    move.values = {{0, 0, 0, 0}, {2, 0, 0, 0}, {2, 4, 0, 0}};
    animation.channels = {spin, move};
    s->animations.push_back(animation);
    return s;
}

// What a plugin's spawner might add to node entities.
struct SpawnTag {};

std::map<int, ecs::Entity> entitiesByNode(ecs::World& world) {
    std::map<int, ecs::Entity> out;
    world.view<SceneNode>().each([&](ecs::Entity e, const SceneNode& n) { out[n.node] = e; });
    return out;
}

void expectMatrixNear(const glm::dmat4& a, const glm::dmat4& b, double tolerance, const std::string& what) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) EXPECT_NEAR(a[c][r], b[c][r], tolerance) << what << " [" << c << "][" << r << "]";
}

class ScenePluginTest : public ::testing::Test {
protected:
    void SetUp() override { app.addPlugin<ScenePlugin>(); }
    ecs::App app;
    std::shared_ptr<const assets::Scene> scene = makeScene();
};

std::size_t shownNodes(const assets::Scene& scene) {
    const std::vector<bool> shown = assets::nodesInScene(scene);
    return static_cast<std::size_t>(std::count(shown.begin(), shown.end(), true));
}

TEST_F(ScenePluginTest, SpawnsOneEntityPerShownNodeWithItsComponents) {
    spawnScene(app.world(), scene);
    ecs::World& world = app.world();
    ASSERT_LT(shownNodes(*scene), scene->nodes.size()) << "the fixture keeps one node outside the default scene";
    EXPECT_EQ(world.size(), shownNodes(*scene));
    const auto byNode = entitiesByNode(world);
    ASSERT_EQ(byNode.size(), shownNodes(*scene));
    const std::vector<glm::dmat4> pose = assets::computeWorldTransforms(*scene, 0.0);
    for (const auto& [node, e] : byNode) {
        const assets::Node& n = scene->nodes[static_cast<std::size_t>(node)];
        EXPECT_EQ(world.get<SceneNode>(e).name, n.name);
        expectMatrixNear(world.get<Transform>(e).world, pose[static_cast<std::size_t>(node)], 0.0, n.name);
        EXPECT_EQ(world.has<MeshRenderer>(e), n.mesh >= 0) << n.name;
        EXPECT_EQ(world.has<CameraComponent>(e), n.camera >= 0) << n.name;
        EXPECT_EQ(world.has<LightComponent>(e), n.light >= 0) << n.name;
    }
    EXPECT_EQ(world.get<MeshRenderer>(byNode.at(1)).mesh, 0);
    EXPECT_EQ(world.get<CameraComponent>(byNode.at(2)).params.name, "eye_camera");
    EXPECT_DOUBLE_EQ(world.get<CameraComponent>(byNode.at(2)).params.yfov, 0.6);
    EXPECT_EQ(world.get<LightComponent>(byNode.at(3)).params.type, assets::LightType::Spot);
    EXPECT_FLOAT_EQ(world.get<LightComponent>(byNode.at(3)).params.intensity, 7.0f);
    // The child's world transform composes its parent's (root at x = 1e5 stays exact in double).
    EXPECT_EQ(glm::dvec3(world.get<Transform>(byNode.at(1)).world[3]), glm::dvec3(1.0e5, 2.0, 5.0));
    ASSERT_TRUE(world.hasResource<SceneAsset>());
    EXPECT_EQ(world.resource<SceneAsset>().scene, scene);
}

TEST_F(ScenePluginTest, SpawnsPosedAtTheRequestedTime) {
    spawnScene(app.world(), scene, 1.5);
    const auto byNode = entitiesByNode(app.world());
    const std::vector<glm::dmat4> pose = assets::computeWorldTransforms(*scene, 1.5);
    expectMatrixNear(app.world().get<Transform>(byNode.at(4)).world, pose[4], 0.0, "mover");
    EXPECT_EQ(glm::dvec3(pose[4][3]), glm::dvec3(2.0, 2.0, 0.0));  // halfway between keys 1 and 2
}

TEST_F(ScenePluginTest, CurrentWorldTransformsReadsTheEcs) {
    spawnScene(app.world(), scene);
    const auto byNode = entitiesByNode(app.world());
    glm::dmat4 moved(1.0);
    moved[3] = glm::dvec4(-7.0, 8.0, 9.0, 1.0);
    app.world().get<Transform>(byNode.at(2)).world = moved;
    const std::vector<glm::dmat4> now = currentWorldTransforms(app.world());
    ASSERT_EQ(now.size(), scene->nodes.size());
    EXPECT_EQ(now[2], moved);
}

TEST_F(ScenePluginTest, RunsSpawnersInOrderAfterTheNodes) {
    std::vector<std::string> calls;
    auto& spawners = app.resource<SceneSpawners>();
    spawners.add("first", [&](ecs::World& world, const assets::Scene& s) {
        EXPECT_EQ(world.count<SceneNode>(), shownNodes(s)) << "spawners see every node entity";
        calls.push_back("first");
    });
    spawners.add("second", [&](ecs::World&, const assets::Scene&) { calls.push_back("second"); });
    spawners.add("first", [&](ecs::World&, const assets::Scene&) { calls.push_back("duplicate"); });
    spawnScene(app.world(), scene);
    EXPECT_EQ(calls, (std::vector<std::string>{"first", "second"}));
}

TEST_F(ScenePluginTest, AThrowingSpawnerLeavesNothingBehind) {
    ecs::World& world = app.world();
    const ecs::Entity bystander = world.create();  // not part of the scene: must survive
    auto& spawners = app.resource<SceneSpawners>();
    spawners.add("tags", [](ecs::World& w, const assets::Scene&) {
        w.view<SceneNode>().each([&](ecs::Entity e, const SceneNode&) { w.emplace<SpawnTag>(e); });
    });
    spawners.add("refuses", [](ecs::World&, const assets::Scene& s) {
        throwInputError(s.displayName(), "nodes[4]", "extensions", "refused by the test");
    });
    EXPECT_THROW(spawnScene(world, scene), InputError);
    EXPECT_EQ(world.size(), 1u);
    EXPECT_TRUE(world.alive(bystander));
    EXPECT_EQ(world.count<SceneNode>(), 0u);
    EXPECT_EQ(world.count<Transform>(), 0u);
    EXPECT_EQ(world.count<MeshRenderer>(), 0u);
    EXPECT_EQ(world.count<SpawnTag>(), 0u);
    EXPECT_FALSE(world.hasResource<SceneAsset>());
}

// A spawner may create entities of its own (e.g. one per particle system) before it refuses the
// data; those must go too, or the scene is half-loaded. spawnScene only destroys the node entities
// today (engine/scene/src/scene_plugin.cpp), so this is disabled until it tracks every entity
// created during the spawn.
TEST_F(ScenePluginTest, AThrowingSpawnerLeavesNoEntityItCreated) {
    ecs::World& world = app.world();
    auto& spawners = app.resource<SceneSpawners>();
    spawners.add("makes_one", [](ecs::World& w, const assets::Scene&) { w.create(); });
    spawners.add("makes_one_then_refuses", [](ecs::World& w, const assets::Scene& s) {
        w.create();
        throwInputError(s.displayName(), "nodes[0]", "extensions", "refused by the test");
    });
    EXPECT_THROW(spawnScene(world, scene), InputError);
    EXPECT_EQ(world.size(), 0u);
}

TEST_F(ScenePluginTest, SimulateToAdvancesRoundedFixedSteps) {
    spawnScene(app.world(), scene);
    EXPECT_EQ(app.frame(), 0u);
    const double dt = app.timeStep();
    for (const double t : {1.0 / 3.0, 0.51, 1.25, 2.6}) {
        simulateTo(app, t);
        const auto steps = static_cast<std::uint64_t>(std::llround(t / dt));
        EXPECT_EQ(app.frame(), steps) << "t = " << t;
        EXPECT_DOUBLE_EQ(simulationTime(app), static_cast<double>(steps) * dt);
        // Every node is where computeWorldTransforms puts it at the simulation time, children included.
        const std::vector<glm::dmat4> expected = assets::computeWorldTransforms(*scene, simulationTime(app));
        const auto byNode = entitiesByNode(app.world());
        for (const auto& [node, e] : byNode)
            expectMatrixNear(app.world().get<Transform>(e).world, expected[static_cast<std::size_t>(node)], 1e-9,
                             "t = " + std::to_string(t) + " node " + scene->nodes[static_cast<std::size_t>(node)].name);
    }
    // The mover really moved: at 2.6 s its animation is clamped at the last key.
    EXPECT_EQ(glm::dvec3(app.world().get<Transform>(entitiesByNode(app.world()).at(4)).world[3]), glm::dvec3(2.0, 4.0, 0.0));
}

TEST_F(ScenePluginTest, SimulateToNeverGoesBackwards) {
    spawnScene(app.world(), scene);
    simulateTo(app, 0.5);
    const std::uint64_t frame = app.frame();
    simulateTo(app, 0.2);
    EXPECT_EQ(app.frame(), frame);
}

// A time that is not finite, negative, or beyond kMaxSimulationSteps is refused before any step.
TEST_F(ScenePluginTest, SimulateToRefusesTimesItCannotReach) {
    spawnScene(app.world(), scene);
    for (const double t : {-1.0, std::nan(""), HUGE_VAL, 1e9, 1e300}) {
        EXPECT_THROW(simulateTo(app, t), InputError) << t;
        EXPECT_EQ(app.frame(), 0u) << t;
    }
    EXPECT_EQ(simulationSteps(kMaxSimulationSteps / 60.0, 1.0 / 60.0), kMaxSimulationSteps);
    try {
        simulateTo(app, 1e300);
    } catch (const InputError& e) {
        EXPECT_LT(std::string(e.what()).size(), 200u) << "a huge time is printed as 1e+300, not 300 digits: " << e.what();
    }
}

TEST(SimulateTo, UsesTheAppsTimeStep) {
    ecs::App app(ecs::AppDesc{.fixedTimeStep = 0.1});
    app.addPlugin<ScenePlugin>();
    auto scene = makeScene();
    spawnScene(app.world(), scene);
    simulateTo(app, 0.26);  // 2.6 steps → 3
    EXPECT_EQ(app.frame(), 3u);
    simulateTo(app, 0.44);  // 4.4 steps → 4
    EXPECT_EQ(app.frame(), 4u);
    const std::vector<glm::dmat4> expected = assets::computeWorldTransforms(*scene, 4 * 0.1);
    const auto byNode = entitiesByNode(app.world());
    expectMatrixNear(app.world().get<Transform>(byNode.at(1)).world, expected[1], 1e-9, "blade");
    // The blade's parent spun: its world position differs from the rest pose.
    EXPECT_GT(glm::length(glm::dvec3(expected[1][3]) - glm::dvec3(1.0e5, 2.0, 5.0)), 0.1);
}

TEST(ScenePlugin, RegistersComponentsAndTheAnimationSystem) {
    ecs::App app;
    EXPECT_TRUE(app.addPlugin<ScenePlugin>());
    EXPECT_FALSE(app.addPlugin<ScenePlugin>()) << "built once";
    EXPECT_TRUE(app.hasResource<SceneSpawners>());
    // Updating with no scene loaded is harmless.
    app.update();
    EXPECT_EQ(app.frame(), 1u);
}

}  // namespace
}  // namespace nimbus::scene
