#pragma once
// Structural checks of a glTF JSON document, run before tinygltf sees it: JSON types, required
// properties, enum values, index ranges, byte ranges of buffer views and accessors (against the
// declared sizes), the node graph (one parent, no cycles), camera / light / transform values, and
// that every referenced buffer and image file exists with the declared size.
//
// What needs the loaded bytes (index values, finite vertex data, key times) is checked while the
// scene is built. Every refusal is one InputError line naming file, object and field.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

namespace nimbus::assets {

struct GltfCheckInput {
    const nlohmann::json* root = nullptr;
    std::string file;                      // for messages
    std::filesystem::path baseDirectory;  // where relative URIs resolve
    bool binary = false;                   // a .glb
    std::optional<std::size_t> binChunkSize;
};

// The asset version and the extensions the file requires.
void checkGltfAsset(const GltfCheckInput& in);

// Buffers, buffer views, accessors, images, samplers, textures, materials, meshes, skins.
void checkGltfData(const GltfCheckInput& in);

// Root extensions, cameras, lights, nodes, scenes, animations.
void checkGltfSceneGraph(const GltfCheckInput& in);

// All of them, asset first, then data (so references into the data are known good when the
// graph is checked).
inline void checkGltfStructure(const GltfCheckInput& in) {
    checkGltfAsset(in);
    checkGltfData(in);
    checkGltfSceneGraph(in);
}

// A top-level array ("nodes") as written, or an empty array when absent. Element type is checked
// by checkGltfData / checkGltfSceneGraph.
const nlohmann::json& topLevelArray(const nlohmann::json& root, const char* key);

// The root KHR_lights_punctual "lights" array, or an empty array.
const nlohmann::json& punctualLights(const nlohmann::json& root);

// Extensions Nimbus understands well enough to accept in "extensionsRequired".
bool isSupportedRequiredExtension(const std::string& name);

}  // namespace nimbus::assets
