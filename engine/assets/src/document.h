#pragma once
// The parsed glTF file behind a Scene: tinygltf's model (buffers, accessors, everything as written)
// plus the raw JSON, kept so plugins can read accessors after loading and the editor can save.
//
// Image pixels are not kept here: they are moved into Scene::images once decoded (the model keeps
// each image's uri / bufferView / mimeType, which is what a writer needs).
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

namespace nimbus::assets {

class Document {
public:
    std::filesystem::path path;
    std::string displayName;  // the file as named in messages
    tinygltf::Model model;
    nlohmann::json json;      // the glTF JSON exactly as read (the JSON chunk for .glb)
};

}  // namespace nimbus::assets
