#include "document/scene_edits.h"

#include <gtest/gtest.h>

#include "nimbus/assets/gltf_file.h"
#include "nimbus/assets/scene.h"
#include "nimbus/base/error.h"

namespace nimbus::sandbox::editor {
namespace {

// root(0) -> a(1) -> b(2); c(3) is a second root; an animation moves b and c.
Json tree() {
    return Json::parse(R"({
      "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0, 3]}],
      "nodes": [{"name": "root", "children": [1]}, {"name": "a", "children": [2]}, {"name": "b"}, {"name": "c", "extras": {"keep": true}}],
      "animations": [{"channels": [{"sampler": 0, "target": {"node": 2, "path": "translation"}},
                                    {"sampler": 0, "target": {"node": 3, "path": "translation"}}],
                      "samplers": [{"input": 0, "output": 1}]}]
    })");
}

assets::Scene load(const Json& json) { return assets::loadSceneFromMemory(assets::encodeGltf(json, {}, false), "edits.gltf"); }

TEST(SceneEdits, SetCreatesObjectsAndNullRemoves) {
    Json root = tree();
    setField(root, 3, "extensions.NIMBUS_participating_media.medium.extinction", 2.5);
    EXPECT_EQ(getField(root, 3, "extensions.NIMBUS_participating_media.medium.extinction"), 2.5);
    setField(root, 3, "translation", Json::array({1, 2, 3}));
    setField(root, 3, "translation.1", 5);
    EXPECT_EQ(getField(root, 3, "translation"), Json::array({1, 5, 3}));
    setField(root, 3, "translation", nullptr);
    EXPECT_TRUE(getField(root, 3, "translation").is_null());
    EXPECT_EQ(getField(root, 3, "extras.keep"), true);
    EXPECT_THROW(setField(root, 3, "translation..x", 1), InputError);
    EXPECT_THROW(setField(root, 3, "extras.keep.deeper", 1), InputError);  // inside a boolean
    EXPECT_THROW(setField(root, 9, "name", "x"), InputError);
}

TEST(SceneEdits, DeleteRemovesTheSubtreeAndRenumbers) {
    Json root = tree();
    deleteNode(root, 1);  // a and b go
    ASSERT_EQ(nodeCount(root), 2);
    EXPECT_EQ(root["nodes"][1]["name"], "c");
    EXPECT_FALSE(root["nodes"][0].contains("children"));  // glTF forbids an empty list
    EXPECT_EQ(root["scenes"][0]["nodes"], Json::array({0, 1}));
    ASSERT_EQ(root["animations"][0]["channels"].size(), 1u);  // b's channel went, c's was renumbered
    EXPECT_EQ(root["animations"][0]["channels"][0]["target"]["node"], 1);
}

TEST(SceneEdits, DeletingEveryAnimatedNodeRemovesTheAnimation) {
    Json root = tree();
    deleteNode(root, 3);
    deleteNode(root, 0);
    EXPECT_EQ(nodeCount(root), 0);
    EXPECT_FALSE(root.contains("animations"));
    EXPECT_FALSE(root["scenes"][0].contains("nodes"));
}

TEST(SceneEdits, ReparentRefusesCycles) {
    Json root = tree();
    EXPECT_THROW(reparentNode(root, 0, 2), InputError);
    EXPECT_THROW(reparentNode(root, 1, 1), InputError);
    reparentNode(root, 3, 2);
    EXPECT_EQ(parentOf(root, 3), 2);
    EXPECT_EQ(sceneRoots(root), std::vector<int>{0});
    reparentNode(root, 2, -1);
    EXPECT_EQ(sceneRoots(root), (std::vector<int>{0, 2}));
    EXPECT_FALSE(root["nodes"][1].contains("children"));
}

TEST(SceneEdits, DuplicateCopiesTheSubtreeWithUniqueNames) {
    Json root = tree();
    const int copy = duplicateNode(root, 1);
    EXPECT_EQ(root["nodes"][static_cast<std::size_t>(copy)]["name"], "a copy");
    EXPECT_EQ(parentOf(root, copy), 0);
    ASSERT_EQ(childrenOf(root, copy).size(), 1u);
    EXPECT_EQ(root["nodes"][static_cast<std::size_t>(childrenOf(root, copy)[0])]["name"], "b copy");
    EXPECT_EQ(root["nodes"][static_cast<std::size_t>(duplicateNode(root, 1))]["name"], "a copy 2");
}

TEST(SceneEdits, RenameKeepsNamesUnique) {
    Json root = tree();
    EXPECT_THROW(renameNode(root, 1, "c"), InputError);
    EXPECT_THROW(renameNode(root, 1, ""), InputError);
    renameNode(root, 1, "arm");
    EXPECT_EQ(findNode(root, "arm"), 1);
}

TEST(SceneEdits, EveryAddedKindLoads) {
    Json root = Json::parse(R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{}]})");
    for (const char* kind : {"emitter", "cloud", "light", "box", "camera"})
        addNode(root, *parseNodeKind(kind), std::string("new ") + kind, -1, glm::dvec3(1.0, 0.0, 0.0));
    addNode(root, NodeKind::Emitter, "flame", 0, glm::dvec3(0.0), "fire");
    EXPECT_EQ(root["scenes"][0]["nodes"].size(), 5u);
    EXPECT_EQ(parentOf(root, 5), 0);
    EXPECT_THROW(addNode(root, NodeKind::Box, "new box"), InputError);  // names stay unique
    EXPECT_FALSE(parseNodeKind("teapot"));
    const assets::Scene scene = load(root);
    ASSERT_EQ(scene.nodes.size(), 6u);
    EXPECT_GE(scene.nodes[1].extensions.size(), 1u);
    EXPECT_GE(scene.nodes[2].light, 0);
    EXPECT_GE(scene.nodes[3].mesh, 0);
    EXPECT_EQ(scene.meshes[0].primitives[0].indices.size(), 36u);
    EXPECT_GE(scene.nodes[4].camera, 0);
}

TEST(SceneEdits, AddedBoxFacesPointOutwards) {
    Json root = Json::parse(R"({"asset": {"version": "2.0"}, "scenes": [{}]})");
    addNode(root, NodeKind::Box, "crate");
    const assets::Scene scene = load(root);
    const assets::Primitive& p = scene.meshes[0].primitives[0];
    for (std::size_t t = 0; t < p.indices.size(); t += 3) {
        const glm::vec3 a = p.positions[p.indices[t]], b = p.positions[p.indices[t + 1]], c = p.positions[p.indices[t + 2]];
        EXPECT_GT(glm::dot(glm::cross(b - a, c - a), (a + b + c) / 3.0f), 0.0f) << "triangle " << t / 3;
    }
}

}  // namespace
}  // namespace nimbus::sandbox::editor
