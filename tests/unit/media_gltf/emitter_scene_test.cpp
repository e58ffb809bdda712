// Tests plugins/participating_media/gltf/src/emitter_scene.cpp through real glTF files: `--time T`
// simulates from 0 with the fixed step and gives exactly what a host stepping once per update gets.
#include <gtest/gtest.h>

#include <cstring>

#include "gltf_fixture.h"
#include "emitter_test_util.h"
#include "nimbus/assets/scene_queries.h"
#include "nimbus/base/error.h"
#include "nimbus/media/nimbus/assets_document.h"
#include "nimbus/media/emitter_scene.h"

namespace nimbus::media {
namespace {

using Json = nlohmann::json;
using test::GltfFixture;

// A scene with a static fire, a vapour trail on a node flying along +X at 10 m/s for 2 s, a plain
// cloud without emitter, and a node without media.
assets::Scene makeScene(GltfFixture& f, const Json& fireEmitter = {{"preset", "fire"}}) {
    f.addNode({{"name", "ground"}});
    f.addNode({{"name", "fire"},
               {"translation", {2.0, 0.0, 0.0}},
               {"extensions", {{"NIMBUS_participating_media", {{"medium", {{"extinction", 6.0}}}, {"emitter", fireEmitter}}}}}});
    f.addCloud("cloud", {0, 5, 0}, {1.0f}, {{"extinction", 1.0}});
    const int jet = f.addNode({{"name", "jet"},
                               {"extensions", {{"NIMBUS_participating_media",
                                                {{"medium", {{"extinction", 3.0}, {"albedo", {1, 1, 1}}}},
                                                 {"emitter", {{"preset", "vapor_trail"}, {"seed", 9}}}}}}}});
    const int times = f.addFloats({0.0f, 2.0f}, "SCALAR");
    f.root()["accessors"][times]["min"] = {0.0};
    f.root()["accessors"][times]["max"] = {2.0};
    const int path = f.addFloats({0, 10, 0, 20, 10, 0}, "VEC3");
    const Json channel = {{"sampler", 0}, {"target", {{"node", jet}, {"path", "translation"}}}};
    const Json sampler = {{"input", times}, {"output", path}, {"interpolation", "LINEAR"}};
    Json animation = Json::object();
    animation["channels"] = Json::array({channel});
    animation["samplers"] = Json::array({sampler});
    f.root()["animations"] = Json::array({animation});
    return assets::loadScene(f.write("emitters"));
}

TEST(EmitterScene, TimeZeroHasNoEmitterParticles) {
    GltfFixture f;
    const assets::Scene scene = makeScene(f);
    EXPECT_TRUE(simulateEmittersTo(AssetsDocument(scene), parseMediaScene(AssetsDocument(scene)), 0.0).empty());
}

TEST(EmitterScene, SimulatingToTMatchesAHostSteppingOncePerUpdateBitForBit) {
    GltfFixture f;
    const assets::Scene scene = makeScene(f);
    const MediaScene media = parseMediaScene(AssetsDocument(scene));
    const double T = 1.5;
    const ParticleSet once = simulateEmittersTo(AssetsDocument(scene), media, T);
    const ParticleSet again = simulateEmittersTo(AssetsDocument(scene), media, T);

    // What the ECS adapter does: one EmitterSimulation per emitter node, stepped once per update.
    std::vector<SceneEmitter> host = makeSceneEmitters(AssetsDocument(scene), media);
    ASSERT_EQ(host.size(), 2u);
    EXPECT_EQ(host[0].node->name, "fire");
    EXPECT_EQ(host[1].node->name, "jet");
    const double dt = 1.0 / 60.0;
    for (int k = 0; k < 90; ++k) {
        const auto w0 = assets::computeWorldTransforms(scene, k * dt);
        const auto w1 = assets::computeWorldTransforms(scene, (k + 1) * dt);
        for (SceneEmitter& e : host) e.simulation.step(k * dt, dt, w0[static_cast<std::size_t>(e.node->node)],
                                                       w1[static_cast<std::size_t>(e.node->node)]);
    }
    ParticleSet stepped;
    for (const SceneEmitter& e : host) e.simulation.appendParticles(stepped, e.node->medium);

    for (const ParticleSet* other : {&again, static_cast<const ParticleSet*>(&stepped)}) {
        ASSERT_EQ(once.size(), other->size());
        EXPECT_TRUE(test::sameBits(once.position, other->position));
        EXPECT_TRUE(test::sameBits(once.radius, other->radius));
        EXPECT_TRUE(test::sameBits(once.sigma, other->sigma));
        EXPECT_TRUE(test::sameBits(once.albedo, other->albedo));
        EXPECT_TRUE(test::sameBits(once.emission, other->emission));
    }
    EXPECT_GT(once.size(), 200u);
}

TEST(EmitterScene, TheTrailFollowsTheAnimatedNodeAndTheFireItsNode) {
    GltfFixture f;
    const assets::Scene scene = makeScene(f);
    const MediaScene media = parseMediaScene(AssetsDocument(scene));
    std::vector<SceneEmitter> emitters = makeSceneEmitters(AssetsDocument(scene), media);
    const double dt = 1.0 / 60.0;
    for (int k = 0; k < 120; ++k) {  // to t = 2 s: the jet flew from x = 0 to x = 20
        const auto w0 = assets::computeWorldTransforms(scene, k * dt);
        const auto w1 = assets::computeWorldTransforms(scene, (k + 1) * dt);
        for (SceneEmitter& e : emitters)
            e.simulation.step(k * dt, dt, w0[static_cast<std::size_t>(e.node->node)], w1[static_cast<std::size_t>(e.node->node)]);
    }
    const EmitterParticles& fire = emitters[0].simulation.particles();
    ASSERT_GT(fire.size(), 20u);
    for (const glm::dvec3& p : fire.position) EXPECT_LT(std::abs(p.x - 2.0), 1.5);

    const EmitterParticles& trail = emitters[1].simulation.particles();
    ASSERT_NEAR(static_cast<double>(trail.size()), 400.0, 1.0);  // 200/s for 2 s, none dead yet
    double lo = 1e9, hi = -1e9;
    for (const glm::dvec3& p : trail.position) {
        lo = std::min(lo, p.x);
        hi = std::max(hi, p.x);
        EXPECT_NEAR(p.y, 10.0, 0.5);
    }
    EXPECT_LT(lo, 0.5);
    EXPECT_GT(hi, 19.5);
}

TEST(EmitterScene, BadEmittersAndTimesAreRefusedNamingFileNodeAndField) {
    GltfFixture f;
    const assets::Scene scene = makeScene(f, {{"preset", "fire"}, {"rate", -3}});
    try {
        (void)parseMediaScene(AssetsDocument(scene));  // a bad emitter is refused at load, not when it is first simulated
        FAIL() << "accepted";
    } catch (const InputError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("emitters.gltf: node \"fire\" (nodes[1]): extensions.NIMBUS_participating_media.emitter.rate: "),
                  std::string::npos)
            << message;
    }

    GltfFixture g;
    const assets::Scene good = makeScene(g);
    const MediaScene goodMedia = parseMediaScene(AssetsDocument(good));
    EXPECT_THROW(simulateEmittersTo(AssetsDocument(good), goodMedia, -1.0), InputError);
    EXPECT_THROW(simulateEmittersTo(AssetsDocument(good), goodMedia, std::nan("")), InputError);
    EXPECT_THROW(simulateEmittersTo(AssetsDocument(good), goodMedia, 1e12), InputError);
}

TEST(EmitterScene, DensityTimesExtinctionMustFitAFloat) {
    GltfFixture f;
    const assets::Scene scene = makeScene(f, {{"density", 1e6}});
    MediaScene media = parseMediaScene(AssetsDocument(scene));
    media.nodes[0].medium.extinction = 1e36f;
    EXPECT_THROW(parseNodeEmitter(AssetsDocument(scene), media.nodes[0]), InputError);
}

}  // namespace
}  // namespace nimbus::media
