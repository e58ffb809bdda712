// Tests plugins/participating_media/gltf/src/media_scene.cpp through real glTF files.
#include "nimbus/media/nimbus/assets_document.h"
#include "nimbus/media/media_scene.h"

#include <gtest/gtest.h>

#include "gltf_fixture.h"
#include "nimbus/assets/scene_queries.h"
#include "nimbus/base/error.h"

namespace nimbus::media {
namespace {

using test::GltfFixture;

const nlohmann::json kSmoke = {{"extinction", 2.5}, {"albedo", {0.9, 0.8, 0.7}}, {"g", 0.4},
                               {"emission", {0.0, 0.1, 0.0}}, {"phase", "rayleigh"}};

TEST(MediaScene, ParsesMediumParticlesAndKeepsRawEmitterAndRender) {
    GltfFixture f;
    f.addNode({{"name", "plain"}});
    const nlohmann::json extra = {{"emitter", {{"rate", 10}}}, {"render", {{"mode", "blocks"}}}};
    f.addCloud("smoke", {0, 0, 0, 1, 2, 3}, {0.5f, 1.5f}, kSmoke, {1.0f, 0.25f}, extra);
    f.addCloud("fog", {4, 5, 6}, {2.0f}, {{"extinction", 0.1}});
    const assets::Scene scene = assets::loadScene(f.write("media"));
    const MediaScene media = parseMediaScene(AssetsDocument(scene));
    ASSERT_EQ(media.nodes.size(), 2u);

    const MediaNode& smoke = media.nodes[0];
    EXPECT_EQ(smoke.node, 1);
    EXPECT_EQ(smoke.name, "smoke");
    EXPECT_FLOAT_EQ(smoke.medium.extinction, 2.5f);
    EXPECT_EQ(smoke.medium.albedo, glm::vec3(0.9f, 0.8f, 0.7f));
    EXPECT_FLOAT_EQ(smoke.medium.g, 0.4f);
    EXPECT_EQ(smoke.medium.emission, glm::vec3(0.0f, 0.1f, 0.0f));
    EXPECT_EQ(smoke.medium.phase, PhaseFunction::Rayleigh);
    ASSERT_EQ(smoke.localPositions.size(), 2u);
    EXPECT_EQ(smoke.localPositions[1], glm::vec3(1, 2, 3));
    EXPECT_EQ(smoke.radii, (std::vector<float>{0.5f, 1.5f}));
    EXPECT_EQ(smoke.densities, (std::vector<float>{1.0f, 0.25f}));
    EXPECT_EQ(smoke.emitter, extra["emitter"]);
    EXPECT_EQ(smoke.render, extra["render"]);

    const MediaNode& fog = media.nodes[1];  // defaults
    EXPECT_EQ(fog.medium.albedo, glm::vec3(1.0f));
    EXPECT_EQ(fog.medium.g, 0.0f);
    EXPECT_EQ(fog.medium.emission, glm::vec3(0.0f));
    EXPECT_EQ(fog.medium.phase, PhaseFunction::HenyeyGreenstein);
    EXPECT_EQ(fog.densities, std::vector<float>{1.0f});
    EXPECT_TRUE(fog.emitter.is_null());
}

TEST(MediaScene, StaticParticlesApplyWorldTransformsAndUniformScale) {
    GltfFixture f;
    const int parent = f.addNode({{"name", "parent"}, {"translation", {1e5, 0.0, -2e5}}, {"scale", {2.0, 2.0, 2.0}}});
    f.root()["scene"] = 0;
    f.root()["scenes"][0]["nodes"] = {parent};
    f.addCloud("child", {1, 0, 0, 0, 1, 0, 0, 0, 1}, {0.5f, 1.0f, 2.0f}, {{"extinction", 3.0}}, {2.0f, 0.0f, 1.0f});
    f.root()["scenes"][0]["nodes"] = {parent};
    f.root()["nodes"][parent]["children"] = {1};
    f.root()["nodes"][1]["rotation"] = {0.0, 0.0, 0.7071067811865476, 0.7071067811865476};  // 90° about +Z
    const assets::Scene scene = assets::loadScene(f.write("transform"));
    const MediaScene media = parseMediaScene(AssetsDocument(scene));
    const ParticleSet set = particlesAtTime(AssetsDocument(scene), media, 0.0);
    ASSERT_EQ(set.size(), 2u);  // density 0 dropped
    // Local (1,0,0) turns to (0,1,0), then scales by 2 and moves by the parent's translation.
    EXPECT_NEAR(set.position[0].x, 1e5, 1e-9);
    EXPECT_NEAR(set.position[0].y, 2.0, 1e-9);
    EXPECT_NEAR(set.position[0].z, -2e5, 1e-9);
    EXPECT_FLOAT_EQ(set.radius[0], 1.0f);  // 0.5 × 2
    EXPECT_FLOAT_EQ(set.sigma[0], 6.0f);   // 3 × density 2
    EXPECT_NEAR(set.position[1].z, -2e5 + 2.0, 1e-9);
    EXPECT_FLOAT_EQ(set.radius[1], 4.0f);
    EXPECT_FLOAT_EQ(set.sigma[1], 3.0f);
}

TEST(MediaScene, NonUniformScaleUsesTheVolumeScale) {
    MediaScene media;
    MediaNode n;
    n.node = 0;
    n.localPositions = {glm::vec3(0.0f)};
    n.radii = {1.0f};
    n.densities = {1.0f};
    media.nodes.push_back(n);
    glm::dmat4 world(1.0);
    world[0][0] = 8.0;  // det 8 → scale 2
    const ParticleSet set = staticParticles(media, {world});
    ASSERT_EQ(set.size(), 1u);
    EXPECT_FLOAT_EQ(set.radius[0], 2.0f);
}

// Loads a scene whose node 0 carries `ext`, expecting an InputError mentioning every needle.
void expectRefusal(const nlohmann::json& ext, std::initializer_list<std::string> needles, GltfFixture f = {}) {
    f.addNode({{"name", "bad"}, {"extensions", {{"NIMBUS_participating_media", ext}}}});
    const std::filesystem::path file = f.write("bad");
    const assets::Scene scene = assets::loadScene(file);
    try {
        parseMediaScene(AssetsDocument(scene));
        ADD_FAILURE() << "accepted: " << ext.dump();
    } catch (const InputError& e) {
        const std::string message = e.what();
        EXPECT_EQ(message.find('\n'), std::string::npos);
        EXPECT_NE(message.find("bad.gltf"), std::string::npos) << message;
        EXPECT_NE(message.find("node \"bad\" (nodes[0])"), std::string::npos) << message;
        for (const std::string& needle : needles) EXPECT_NE(message.find(needle), std::string::npos) << message;
    }
}

TEST(MediaScene, RefusesMalformedMedia) {
    const nlohmann::json ok = {{"extinction", 1.0}};
    expectRefusal({{"medium", ok}, {"smoke", 1}}, {"NIMBUS_participating_media.smoke", "unknown key"});
    expectRefusal({{"particles", nlohmann::json::object()}}, {"medium", "required"});
    expectRefusal(nlohmann::json::array(), {"must be an object"});
    expectRefusal({{"medium", nlohmann::json::object()}}, {"medium.extinction", "required"});
    expectRefusal({{"medium", {{"extinction", 0.0}}}}, {"medium.extinction", "> 0"});
    expectRefusal({{"medium", {{"extinction", -2.0}}}}, {"medium.extinction"});
    expectRefusal({{"medium", {{"extinction", "dense"}}}}, {"medium.extinction", "number"});
    expectRefusal({{"medium", {{"extinction", 1.0}, {"albedo", {0.5, 1.5, 0.5}}}}}, {"medium.albedo[1]", "[0, 1]"});
    expectRefusal({{"medium", {{"extinction", 1.0}, {"albedo", {0.5, 0.5}}}}}, {"medium.albedo", "3 numbers"});
    expectRefusal({{"medium", {{"extinction", 1.0}, {"g", 1.0}}}}, {"medium.g", "(-1, 1)"});
    expectRefusal({{"medium", {{"extinction", 1.0}, {"emission", {0.0, -1.0, 0.0}}}}}, {"medium.emission[1]"});
    expectRefusal({{"medium", {{"extinction", 1.0}, {"phase", "mie"}}}}, {"medium.phase", "mie"});
    expectRefusal({{"medium", {{"extinction", 1.0}, {"color", 1}}}}, {"medium.color", "unknown key"});
}

TEST(MediaScene, RefusesMalformedVolumes) {
    const nlohmann::json ok = {{"extinction", 1.0}};
    expectRefusal({{"medium", ok}, {"volume", {{"shape", "cone"}, {"size", {1, 1, 1}}}}}, {"volume.shape", "cone"});
    expectRefusal({{"medium", ok}, {"volume", {{"size", {1, 1, 1}}}}}, {"volume.shape", "required"});
    expectRefusal({{"medium", ok}, {"volume", {{"shape", "box"}}}}, {"volume.size", "required"});
    expectRefusal({{"medium", ok}, {"volume", {{"shape", "box"}, {"size", {1, 0, 1}}}}}, {"volume.size[1]", "> 0"});
    expectRefusal({{"medium", ok}, {"volume", {{"shape", "box"}, {"size", {1, -2, 1}}}}}, {"volume.size[1]", "> 0"});
    expectRefusal({{"medium", ok}, {"volume", {{"shape", "box"}, {"size", {1, 1}}}}}, {"volume.size", "3 numbers"});
    expectRefusal({{"medium", ok}, {"volume", {{"shape", "box"}, {"size", {1, 1, 1}}, {"colour", 1}}}}, {"volume.colour", "unknown key"});
}

TEST(MediaScene, AGeneratorMakesTheNodesCloud) {
    GltfFixture f;
    f.addNode({{"name", "cumulus"},
               {"extensions", {{"NIMBUS_participating_media", {{"medium", {{"extinction", 0.5}}},
                                                              {"generator", {{"kind", "ellipsoids"}, {"seed", 9}, {"particles", 300}, {"size", {6, 3, 4}}}}}}}}});
    const assets::Scene scene = assets::loadScene(f.write("generated"));
    const MediaScene media = parseMediaScene(AssetsDocument(scene));
    EXPECT_EQ(media.nodes.at(0).localPositions.size(), 300u);
    EXPECT_EQ(staticParticles(media, {glm::dmat4(1.0)}).size(), 300u);
}

TEST(MediaScene, RefusesMalformedGenerators) {
    const nlohmann::json ok = {{"extinction", 1.0}};
    auto generator = [&](const nlohmann::json& g) { return nlohmann::json{{"medium", ok}, {"generator", g}}; };
    expectRefusal(generator({{"size", {1, 1, 1}}}), {"generator.kind", "required"});
    expectRefusal(generator({{"kind", "fractal"}, {"size", {1, 1, 1}}}), {"generator.kind", "fractal"});
    expectRefusal(generator({{"kind", "ellipsoids"}}), {"generator.size", "required"});
    expectRefusal(generator({{"kind", "ellipsoids"}, {"size", {1, 0, 1}}}), {"generator.size[1]", "> 0"});
    expectRefusal(generator({{"kind", "ellipsoids"}, {"size", {1, 1, 1}}, {"particles", 0}}), {"generator.particles", "1.."});
    expectRefusal(generator({{"kind", "ellipsoids"}, {"size", {1, 1, 1}}, {"particles", 1 << 21}}), {"generator.particles"});
    expectRefusal(generator({{"kind", "ellipsoids"}, {"size", {1, 1, 1}}, {"radius", {0.5, 0.2}}}), {"generator.radius", "min <= max"});
    expectRefusal(generator({{"kind", "diamond-square"}, {"size", {1, 1, 1}}, {"roughness", 1.0}}), {"generator.roughness", "(0, 1)"});
    expectRefusal(generator({{"kind", "diamond-square"}, {"size", {1, 1, 1}}, {"coverage", -0.5}}), {"generator.coverage", "[0, 1)"});
    expectRefusal(generator({{"kind", "diamond-square"}, {"size", {1, 1, 1}}, {"height", 2}}), {"generator.height", "unknown key"});
}

TEST(MediaScene, RefusesMalformedNoise) {
    const nlohmann::json ok = {{"extinction", 1.0}};
    auto noisy = [&](const nlohmann::json& noise) {
        return nlohmann::json{{"medium", ok}, {"volume", {{"shape", "box"}, {"size", {1, 1, 1}}, {"noise", noise}}}};
    };
    expectRefusal(noisy({{"kind", "perlin"}}), {"volume.noise.kind", "perlin"});
    expectRefusal(noisy({{"octaves", 2}}), {"volume.noise.kind", "required"});
    expectRefusal(noisy({{"kind", "value"}, {"octaves", 0}}), {"volume.noise.octaves", "1..12"});
    expectRefusal(noisy({{"kind", "value"}, {"octaves", 2.5}}), {"volume.noise.octaves", "integer"});
    expectRefusal(noisy({{"kind", "value"}, {"frequency", 0}}), {"volume.noise.frequency", "> 0"});
    expectRefusal(noisy({{"kind", "value"}, {"frequency", -1}}), {"volume.noise.frequency", "> 0"});
    expectRefusal(noisy({{"kind", "sines"}, {"gain", 1.5}}), {"volume.noise.gain", "(0, 1]"});
    expectRefusal(noisy({{"kind", "sines"}, {"coverage", 1.0}}), {"volume.noise.coverage", "[0, 1)"});
    expectRefusal(noisy({{"kind", "sines"}, {"falloff", -0.1}}), {"volume.noise.falloff", "[0, 1]"});
    expectRefusal(noisy({{"kind", "sines"}, {"seed", -1}}), {"volume.noise.seed"});
    expectRefusal(noisy({{"kind", "sines"}, {"velocity", {1, 2}}}), {"volume.noise.velocity", "3 numbers"});
    expectRefusal(noisy({{"kind", "sines"}, {"turbulence", 1}}), {"volume.noise.turbulence", "unknown key"});
    expectRefusal(noisy(3), {"volume.noise", "object"});
}

// A volume is placed by its node's world transform and names its node for the renderers' messages.
TEST(MediaScene, VolumesTakeTheirNodesTransform) {
    GltfFixture f;
    f.addNode({{"name", "bank"},
               {"translation", {1.0, 2.0, 3.0}},
               {"extensions", {{"NIMBUS_participating_media", {{"medium", {{"extinction", 0.5}}}, {"volume", {{"shape", "ellipsoid"}, {"size", {4, 2, 6}}}}}}}}});
    const assets::Scene scene = assets::loadScene(f.write("bank"));
    const MediaScene media = parseMediaScene(AssetsDocument(scene));
    ASSERT_EQ(media.nodes.size(), 1u);
    ASSERT_TRUE(media.nodes[0].volume.has_value());
    EXPECT_EQ(media.nodes[0].volume->shape, VolumeShape::Ellipsoid);
    const std::vector<Volume> volumes = sceneVolumes(media, AssetsDocument(scene).worldTransforms(0.0));
    ASSERT_EQ(volumes.size(), 1u);
    EXPECT_EQ(volumes[0].size, glm::dvec3(4, 2, 6));
    EXPECT_TRUE(volumeContains(volumes[0], {1.0, 2.0, 5.9}));
    EXPECT_FALSE(volumeContains(volumes[0], {1.0, 2.0, 6.1}));
    EXPECT_NE(volumes[0].origin.find("bank.gltf: node \"bank\" (nodes[0])"), std::string::npos) << volumes[0].origin;
    EXPECT_FALSE(volumes[0].noise.has_value());
}

TEST(MediaScene, NoiseDefaultsFollowItsKind) {
    GltfFixture f;
    const nlohmann::json noise = {{"kind", "sines"}, {"frequency", 0.5}, {"velocity", {1.0, 0.0, 0.5}}};
    f.addNode({{"name", "haze"},
               {"extensions", {{"NIMBUS_participating_media", {{"medium", {{"extinction", 0.5}}}, {"volume", {{"shape", "box"}, {"size", {4, 2, 6}}, {"noise", noise}}}}}}}});
    const assets::Scene scene = assets::loadScene(f.write("haze"));
    const MediaScene media = parseMediaScene(AssetsDocument(scene));
    const NoiseField& n = *media.nodes.at(0).volume->noise;
    EXPECT_EQ(n.kind, NoiseKind::Sines);
    EXPECT_EQ(n.octaves, 4);
    EXPECT_DOUBLE_EQ(n.gain, 0.707);  // Gardner's
    EXPECT_DOUBLE_EQ(n.frequency, 0.5);
    EXPECT_EQ(n.seed, 0u);
    const std::vector<Volume> later = sceneVolumes(media, AssetsDocument(scene).worldTransforms(2.0), 2.0);
    EXPECT_EQ(later.at(0).drift, glm::dvec3(2.0, 0.0, 1.0));
}

TEST(MediaScene, RefusesMalformedParticles) {
    const nlohmann::json medium = {{"extinction", 1.0}};
    {
        GltfFixture f;
        const int p = f.addFloats({0, 0, 0, 1, 1, 1}, "VEC3");
        const int r = f.addFloats({1.0f}, "SCALAR");
        expectRefusal({{"medium", medium}, {"particles", {{"position", p}, {"radius", r}}}}, {"particles.radius", "count"}, f);
    }
    {
        GltfFixture f;
        const int p = f.addFloats({0, 0, 0, 1, 1, 1}, "VEC3");
        const int r = f.addFloats({1.0f, 0.0f}, "SCALAR");
        expectRefusal({{"medium", medium}, {"particles", {{"position", p}, {"radius", r}}}}, {"particles.radius", "element 1"}, f);
    }
    {
        GltfFixture f;
        const int p = f.addFloats({0, 0, 0}, "VEC3");
        const int r = f.addFloats({1.0f}, "SCALAR");
        const int d = f.addFloats({-1.0f}, "SCALAR");
        expectRefusal({{"medium", medium}, {"particles", {{"position", p}, {"radius", r}, {"density", d}}}},
                      {"particles.density", "element 0"}, f);
    }
    {
        GltfFixture f;
        const int r = f.addFloats({1.0f}, "SCALAR");
        expectRefusal({{"medium", medium}, {"particles", {{"position", r}, {"radius", r}}}}, {"particles.position"}, f);
    }
    {
        GltfFixture f;
        const int r = f.addFloats({1.0f}, "SCALAR");
        expectRefusal({{"medium", medium}, {"particles", {{"position", 42}, {"radius", r}}}}, {"particles.position"}, f);
    }
    {
        GltfFixture f;
        const int p = f.addFloats({0, 0, 0}, "VEC3");
        expectRefusal({{"medium", medium}, {"particles", {{"position", p}}}}, {"particles.radius", "required"}, f);
        expectRefusal({{"medium", medium}, {"particles", {{"position", p}, {"radius", -1}}}}, {"particles.radius", "accessor index"}, f);
        expectRefusal({{"medium", medium}, {"particles", {{"position", p}, {"radius", 0}, {"size", 1}}}}, {"particles.size", "unknown key"}, f);
    }
}

}  // namespace
}  // namespace nimbus::media
