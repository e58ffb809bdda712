// MediaPlugin (plugins/participating_media/ecs/src/media_plugin.cpp): what build() registers and in
// which phases, that adding it twice changes nothing, that its systems do nothing (and create no
// renderer) without media, that a scene with a bad media extension leaves no entity behind, and
// that gatherParticles after stepping the App is bit for bit media::particlesAtTime (the path of
// hosts without the ECS, and of the reference renderer's `--time`). No GL: rendering stays off.
#include "nimbus/media/nimbus/assets_document.h"
#include "nimbus/media/ecs/media_plugin.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

#include "nimbus/base/error.h"
#include "nimbus/base/settings.h"
#include "nimbus/media/media_scene.h"
#include "particles/particles_technique.h"
#include "nimbus/render/render_plugin.h"
#include "nimbus/scene/scene_plugin.h"

namespace nimbus::media::ecs {
namespace {

namespace phases = nimbus::ecs::phases;

std::filesystem::path contentScene(const std::string& name) {
    return std::filesystem::path(NIMBUS_CONTENT_DIR_FOR_TESTS) / "scenes" / (name + ".gltf");
}
std::filesystem::path mediaTestScene(const std::string& name) {
    return std::filesystem::path(NIMBUS_TEST_DATA_DIR) / "media_scenes" / (name + ".gltf");
}

std::size_t indexOf(const std::vector<std::string>& order, const std::string& name) {
    return static_cast<std::size_t>(std::find(order.begin(), order.end(), name) - order.begin());
}

class MediaPluginTest : public ::testing::Test {
protected:
    MediaPluginTest() {
        app.insertResource<Settings>();
        app.addPlugin<MediaPlugin>();
    }
    nimbus::ecs::World& world() { return app.world(); }
    nimbus::ecs::App app;
};

TEST_F(MediaPluginTest, BuildRegistersComponentsSystemsAndResources) {
    for (const char* name : {"Medium", "ParticleCloud", "Emitter"})
        EXPECT_NE(app.components().find(name), nullptr) << name;
    // What the plugin depends on is built with it.
    EXPECT_TRUE(app.hasPlugin("nimbus.scene"));
    EXPECT_TRUE(app.hasPlugin("nimbus.render"));

    const auto simulate = app.scheduler().systemOrder(phases::kSimulate);
    ASSERT_LT(indexOf(simulate, kEmitSystem), simulate.size()) << "media.emit runs in Simulate";
    ASSERT_LT(indexOf(simulate, scene::kAnimateSystem), simulate.size());
    EXPECT_GT(indexOf(simulate, kEmitSystem), indexOf(simulate, scene::kAnimateSystem))
        << "emitters step with their node's pose at the end of the step, which the animation sets";

    const auto prepare = app.scheduler().systemOrder(phases::kPrepare);
    EXPECT_LT(indexOf(prepare, kLightSliceSystem), prepare.size()) << "media.light_slices runs in Prepare";

    const auto render = app.scheduler().systemOrder(phases::kRender);
    ASSERT_LT(indexOf(render, kRenderSystem), render.size()) << "media.render runs in Render";
    ASSERT_LT(indexOf(render, render::kRenderFrameSystem), render.size());
    EXPECT_LT(indexOf(render, kRenderSystem), indexOf(render, render::kRenderFrameSystem))
        << "the renderer must be registered as an extension before the frame is drawn";

    // Each system in exactly one phase.
    for (const auto& phase : app.scheduler().phaseOrder()) {
        if (phase == phases::kSimulate || phase == phases::kPrepare || phase == phases::kRender) continue;
        const auto order = app.scheduler().systemOrder(phase);
        for (const char* name : {kEmitSystem, kLightSliceSystem, kRenderSystem})
            EXPECT_EQ(indexOf(order, name), order.size()) << name << " also in " << phase;
    }

    EXPECT_TRUE(app.hasResource<MediaFrame>());
    EXPECT_TRUE(app.hasResource<MediaRendererState>());
    const auto& spawners = app.resource<scene::SceneSpawners>().list;
    EXPECT_EQ(std::count_if(spawners.begin(), spawners.end(), [](const auto& s) { return s.first == "media"; }), 1);
    for (const char* key : {"mode", "slices", "slice_resolution", "soft_particles", "layer_light", "media_scale"})
        EXPECT_TRUE(app.resource<Settings>().declared(key)) << key;
}

TEST_F(MediaPluginTest, AddingThePluginTwiceIsHarmless) {
    auto systemsIn = [&](const char* phase) { return app.scheduler().systemOrder(phase); };
    const auto simulate = systemsIn(phases::kSimulate), prepare = systemsIn(phases::kPrepare),
               render = systemsIn(phases::kRender);
    const std::size_t spawners = app.resource<scene::SceneSpawners>().list.size();
    const std::size_t components = app.components().all().size();
    const std::size_t declarations = app.resource<Settings>().declarations().size();

    EXPECT_FALSE(app.addPlugin<MediaPlugin>()) << "a second MediaPlugin is not built";
    EXPECT_FALSE(app.addPlugin<scene::ScenePlugin>());
    EXPECT_FALSE(app.addPlugin<render::RenderPlugin>());

    EXPECT_EQ(systemsIn(phases::kSimulate), simulate);
    EXPECT_EQ(systemsIn(phases::kPrepare), prepare);
    EXPECT_EQ(systemsIn(phases::kRender), render);
    EXPECT_EQ(app.resource<scene::SceneSpawners>().list.size(), spawners);
    EXPECT_EQ(app.components().all().size(), components);
    EXPECT_EQ(app.resource<Settings>().declarations().size(), declarations);

    // And a scene spawns once: one medium per media node, one emitter simulation per emitter.
    const auto scene = std::make_shared<const assets::Scene>(assets::loadScene(contentScene("campfire")));
    scene::spawnScene(world(), scene);
    EXPECT_EQ(world().count<MediumComponent>(), 2u);  // fire and smoke
    EXPECT_EQ(world().count<EmitterComponent>(), 2u);
    scene::simulateTo(app, 1.0);
    ParticleSet gathered;
    gatherParticles(world(), gathered);
    const ParticleSet expected = particlesAtTime(AssetsDocument(*scene), parseMediaScene(AssetsDocument(*scene)), 1.0);
    EXPECT_EQ(gathered.size(), expected.size()) << "emitters stepped once per update, not twice";
}

// A scene with meshes and a light but no NIMBUS_participating_media node.
std::shared_ptr<const assets::Scene> sceneWithoutMedia() {
    auto s = std::make_shared<assets::Scene>();
    assets::Primitive p;
    p.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    p.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
    p.indices = {0, 1, 2};
    p.boundsMax = {1, 1, 0};
    s->meshes.push_back({"tri", {p}});
    s->lights.push_back(assets::Light{});
    assets::Node mesh, sun;
    mesh.name = "mesh";
    mesh.mesh = 0;
    sun.name = "sun";
    sun.light = 0;
    s->nodes = {mesh, sun};
    s->rootNodes = {0, 1};
    return s;
}

TEST_F(MediaPluginTest, WithoutMediaEverySystemDoesNothingAndNoRendererIsMade) {
    // A setting the gather system would copy into MediaFrame if it ran past its early return.
    app.resource<Settings>().assign("mode=blocks");
    scene::spawnScene(world(), sceneWithoutMedia());
    for (int i = 0; i < 5; ++i) app.update();  // every phase; rendering is off, as for simulation-only hosts
    EXPECT_EQ(world().count<MediumComponent>(), 0u);
    EXPECT_EQ(world().count<ParticleCloud>(), 0u);
    EXPECT_EQ(world().count<EmitterComponent>(), 0u);
    const MediaFrame& frame = app.resource<MediaFrame>();
    EXPECT_TRUE(frame.particles.empty());
    EXPECT_EQ(frame.particles.position.capacity(), 0u) << "nothing allocated";
    EXPECT_TRUE(frame.settings.mode.empty()) << "media.light_slices read the settings with no medium";
    EXPECT_EQ(app.resource<MediaRendererState>().renderer, nullptr);
    EXPECT_TRUE(app.resource<render::RenderExtensions>().list.empty());
}

TEST_F(MediaPluginTest, WithMediaTheRendererIsMadeAndRegistered) {
    // The counterpart of the test above, so that one can fail: the same updates with a medium.
    const auto scene = std::make_shared<const assets::Scene>(assets::loadScene(mediaTestScene("absorber")));
    scene::spawnScene(world(), scene);
    EXPECT_EQ(world().count<ParticleCloud>(), 1u);
    app.update();
    EXPECT_FALSE(app.resource<MediaFrame>().particles.empty());
    const auto& state = app.resource<MediaRendererState>();
    ASSERT_NE(state.renderer, nullptr);
    const auto& list = app.resource<render::RenderExtensions>().list;
    EXPECT_EQ(std::count(list.begin(), list.end(), state.extension.get()), 1);
    app.update();
    EXPECT_EQ(std::count(list.begin(), list.end(), state.extension.get()), 1) << "registered once, not per frame";
}

// A valid scene with one node's media extension replaced by `bad`.
std::shared_ptr<const assets::Scene> withBadNode(const nlohmann::json& bad) {
    auto s = std::make_shared<assets::Scene>(assets::loadScene(mediaTestScene("absorber")));
    for (assets::Node& n : s->nodes)
        if (n.extensions.contains(assets::kMediaExtension)) n.extensions[assets::kMediaExtension] = bad;
    return s;
}

TEST_F(MediaPluginTest, ABadMediaExtensionLeavesNoEntityBehind) {
    const auto good = assets::loadScene(mediaTestScene("absorber"));
    nlohmann::json valid;
    for (const assets::Node& n : good.nodes)
        if (n.extensions.contains(assets::kMediaExtension)) valid = n.extensions[assets::kMediaExtension];
    ASSERT_TRUE(valid.contains("particles"));

    std::vector<std::pair<std::string, nlohmann::json>> cases;
    auto variant = [&](const std::string& what, auto change) {
        nlohmann::json j = valid;
        change(j);
        cases.emplace_back(what, j);
    };
    variant("negative extinction", [](nlohmann::json& j) { j["medium"]["extinction"] = -1.0; });
    variant("no medium", [](nlohmann::json& j) { j.erase("medium"); });
    variant("unknown phase", [](nlohmann::json& j) { j["medium"]["phase"] = "mie"; });
    variant("accessor out of range", [](nlohmann::json& j) { j["particles"]["radius"] = 999; });
    variant("unknown emitter key", [](nlohmann::json& j) { j["emitter"] = {{"preset", "smoke"}, {"sped", 1.0}}; });
    variant("bad emitter value", [](nlohmann::json& j) { j["emitter"] = {{"lifetime", 0.0}}; });
    variant("unknown render mode", [](nlohmann::json& j) { j["render"] = {{"mode", "voxels"}}; });
    variant("unknown block shading", [](nlohmann::json& j) { j["render"] = {{"block_shading", "exactly"}}; });
    variant("unknown node key", [](nlohmann::json& j) { j["fog"] = true; });

    for (const auto& [what, bad] : cases) {
        nimbus::ecs::App fresh;
        fresh.insertResource<Settings>();
        fresh.addPlugin<MediaPlugin>();
        EXPECT_THROW(scene::spawnScene(fresh.world(), withBadNode(bad)), InputError) << what;
        EXPECT_EQ(fresh.world().size(), 0u) << what << ": entities left behind";
        EXPECT_EQ(fresh.world().count<MediumComponent>(), 0u) << what;
        fresh.update();  // and nothing runs on a half-spawned scene
        EXPECT_TRUE(fresh.resource<MediaFrame>().particles.empty()) << what;
    }
    // Two media nodes, the second one bad: the first one's components are not left behind either.
    auto campfire = std::make_shared<assets::Scene>(assets::loadScene(contentScene("campfire")));
    for (assets::Node& n : campfire->nodes)
        if (n.name == "smoke") n.extensions[assets::kMediaExtension]["emitter"]["rate"] = -1.0;
    {
        nimbus::ecs::App fresh;
        fresh.insertResource<Settings>();
        fresh.addPlugin<MediaPlugin>();
        EXPECT_THROW(scene::spawnScene(fresh.world(), campfire), InputError);
        EXPECT_EQ(fresh.world().size(), 0u);
        EXPECT_EQ(fresh.world().count<EmitterComponent>(), 0u);
    }
    // The unmodified scene spawns: the failures above are the bad values, not the fixture.
    scene::spawnScene(world(), std::make_shared<const assets::Scene>(good));
    EXPECT_GT(world().size(), 0u);
    EXPECT_EQ(world().count<MediumComponent>(), 1u);
}

// Whether b is a reordering of a (every particle's values bit for bit), to tell an order difference
// from different particles in a failure message.
bool samePermuted(const ParticleSet& a, const ParticleSet& b) {
    if (a.size() != b.size()) return false;
    auto key = [](const ParticleSet& s, std::size_t i) {
        return std::make_tuple(s.position[i].x, s.position[i].y, s.position[i].z, s.radius[i], s.sigma[i]);
    };
    std::vector<std::size_t> ia(a.size()), ib(b.size());
    for (std::size_t i = 0; i < a.size(); ++i) ia[i] = ib[i] = i;
    std::sort(ia.begin(), ia.end(), [&](std::size_t x, std::size_t y) { return key(a, x) < key(a, y); });
    std::sort(ib.begin(), ib.end(), [&](std::size_t x, std::size_t y) { return key(b, x) < key(b, y); });
    for (std::size_t i = 0; i < a.size(); ++i) {
        const std::size_t x = ia[i], y = ib[i];
        if (key(a, x) != key(b, y) || a.albedo[x] != b.albedo[y] || a.emission[x] != b.emission[y] || a.g[x] != b.g[y] ||
            a.phase[x] != b.phase[y])
            return false;
    }
    return true;
}

// A scene refused for its render overrides must leave none of the values it set before the failing
// check in Settings (applyRenderOverrides sets key by key, then checks them all): otherwise the next
// scene loaded into the same App is refused for the earlier scene's value.
TEST_F(MediaPluginTest, ARefusedSceneLeavesNoRenderSettingBehind) {
    const auto good = assets::loadScene(mediaTestScene("absorber"));
    nlohmann::json bad;
    for (const assets::Node& n : good.nodes)
        if (n.extensions.contains(assets::kMediaExtension)) bad = n.extensions[assets::kMediaExtension];
    bad["render"] = {{"mode", "blocks"}, {"slices", 999}};  // slices out of 4..32
    EXPECT_THROW(scene::spawnScene(world(), withBadNode(bad)), InputError);
    EXPECT_FALSE(app.resource<Settings>().has("mode")) << "render.mode of the refused scene was kept";
    EXPECT_FALSE(app.resource<Settings>().has("slices")) << "render.slices of the refused scene was kept";
    EXPECT_NO_THROW(scene::spawnScene(world(), std::make_shared<const assets::Scene>(good)));
    EXPECT_NO_THROW(app.update());
}

// The scene format's render block (docs/scene-format.schema.json) names exactly the settings the
// App declares, so a scene can set every one and nothing else; sandbox_cli_test checks the whole
// block against `sandbox settings --schema`.
TEST_F(MediaPluginTest, TheSchemaNamesEveryDeclaredSetting) {
    std::ifstream in(NIMBUS_DOCS_DIR "/scene-format.schema.json");
    ASSERT_TRUE(in);
    const nlohmann::json schema = nlohmann::json::parse(in);
    std::set<std::string> documented, declared;
    for (const auto& [key, value] : schema["$defs"]["render"]["properties"].items()) documented.insert(key);
    for (const SettingSpec& d : app.resource<Settings>().declarations()) declared.insert(d.key);
    EXPECT_EQ(documented, declared);
}

// Every tier reads, picks the lighting it promises, and keeps the mode.
TEST_F(MediaPluginTest, EveryQualityTierReads) {
    const std::map<std::string, ParticleLighting> lighting = {
        {"fast", ParticleLighting::Particle}, {"balanced", ParticleLighting::ParticleExact}, {"exact", ParticleLighting::Fragment}};
    EXPECT_EQ(app.resource<Settings>().find("quality")->words, (std::vector<std::string>{"exact", "balanced", "fast"}));
    for (const auto& [name, expected] : lighting) {
        Settings settings = app.resource<Settings>();
        settings.set("quality", name);
        MediaRenderSettings parsed;
        ASSERT_NO_THROW(parsed = readMediaSettings(&settings)) << name;
        EXPECT_EQ(techniqueSettings<ParticlesSettings>(parsed).lighting, expected) << name;
        EXPECT_EQ(parsed.mode, "particles") << name << ": a tier keeps the mode";
    }
}

TEST_F(MediaPluginTest, AnUnknownQualityIsRefusedNamingWhereItWasSet) {
    Settings settings = app.resource<Settings>();
    settings.set("quality", "turbo", "scene.gltf: node \"fog\": render.quality");
    try {
        (void)readMediaSettings(&settings);
        FAIL() << "quality=turbo was accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("render.quality"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("exact, balanced or fast"), std::string::npos) << e.what();
    }
}

void expectBitIdentical(const ParticleSet& a, const ParticleSet& b, const std::string& what_) {
    ASSERT_EQ(a.size(), b.size()) << what_;
    const std::string what = what_ + (samePermuted(a, b) ? " (the same particles in another order)" : "");
    auto same = [](const auto& x, const auto& y) {
        return x.size() == y.size() && (x.empty() || std::memcmp(x.data(), y.data(), x.size() * sizeof(x[0])) == 0);
    };
    EXPECT_TRUE(same(a.position, b.position)) << what << ": positions";
    EXPECT_TRUE(same(a.radius, b.radius)) << what << ": radii";
    EXPECT_TRUE(same(a.sigma, b.sigma)) << what << ": sigma";
    EXPECT_TRUE(same(a.albedo, b.albedo)) << what << ": albedo";
    EXPECT_TRUE(same(a.emission, b.emission)) << what << ": emission";
    EXPECT_TRUE(same(a.g, b.g)) << what << ": g";
    EXPECT_TRUE(same(a.phase, b.phase)) << what << ": phase";
}

// Steps an App with the plugin to `time` and compares what it gathers with the non-ECS path.
void expectGatherEqualsParticlesAtTime(const std::filesystem::path& path, double time) {
    nimbus::ecs::App app;
    app.insertResource<Settings>();
    app.addPlugin<MediaPlugin>();
    const auto scene = std::make_shared<const assets::Scene>(assets::loadScene(path));
    scene::spawnScene(app.world(), scene);
    scene::simulateTo(app, time);
    ParticleSet gathered;
    gatherParticles(app.world(), gathered);
    const ParticleSet expected = particlesAtTime(AssetsDocument(*scene), parseMediaScene(AssetsDocument(*scene)), time);
    EXPECT_GT(expected.size(), 10u) << path.filename() << ": the comparison needs particles";
    expectBitIdentical(gathered, expected, path.filename().string() + " at t=" + std::to_string(time));
}

// The content scenes at the times they are rendered (tools/scenegen/make_scenes.py TIMES), a static
// cloud, and a static cloud on a rotated, scaled node.
TEST(MediaPluginGather, SmokeEqualsParticlesAtTime) { expectGatherEqualsParticlesAtTime(contentScene("smoke"), 8.0); }
TEST(MediaPluginGather, JetEqualsParticlesAtTime) { expectGatherEqualsParticlesAtTime(contentScene("jet"), 6.0); }
TEST(MediaPluginGather, ExplosionEqualsParticlesAtTime) {
    expectGatherEqualsParticlesAtTime(contentScene("explosion"), 0.8);
}
TEST(MediaPluginGather, CloudEqualsParticlesAtTime) { expectGatherEqualsParticlesAtTime(contentScene("cloud"), 0.0); }
TEST(MediaPluginGather, TransformedCloudEqualsParticlesAtTime) {
    expectGatherEqualsParticlesAtTime(mediaTestScene("unseen_transformed_node"), 0.0);
}
// FAILS today: the same particles bit for bit, but not in the same order. campfire has two emitter
// nodes (fire, then smoke); particlesAtTime appends them in node order, gatherParticles in the
// order the ECS view visits the entities, which puts the smoke first.
TEST(MediaPluginGather, CampfireEqualsParticlesAtTime) {
    expectGatherEqualsParticlesAtTime(contentScene("campfire"), 4.0);
}

}  // namespace
}  // namespace nimbus::media::ecs
