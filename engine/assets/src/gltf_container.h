#pragma once
// Reading a glTF file's bytes and finding its JSON: a .gltf is JSON text, a .glb is a binary
// container (12-byte header, a JSON chunk, an optional BIN chunk). Which one is decided by the
// content ("glTF" magic), never by the file extension.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace nimbus::assets {

struct GltfSource {
    std::vector<unsigned char> bytes;  // the whole file
    bool binary = false;               // a .glb container
    std::size_t jsonOffset = 0;        // the JSON text inside `bytes`
    std::size_t jsonSize = 0;
    std::optional<std::size_t> binChunkSize;  // payload size of the GLB BIN chunk, when there is one
    nlohmann::json json;                      // the parsed JSON
};

// Reads and splits the file, parses the JSON. Throws InputError naming `displayName` for a missing,
// empty, truncated or inconsistent file and for malformed JSON (with line and column).
GltfSource readGltfSource(const std::filesystem::path& file, const std::string& displayName);

// The same for bytes already in memory (the editor's edited document).
GltfSource parseGltfBytes(std::vector<unsigned char> bytes, const std::string& displayName);

}  // namespace nimbus::assets
