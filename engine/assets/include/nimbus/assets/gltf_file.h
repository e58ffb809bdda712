#pragma once
// A glTF file as JSON plus its GLB BIN chunk, for tools that rewrite files (the editor): read exactly
// as written, edited as JSON, encoded back as .gltf text or a .glb container.
//
// Does not: validate the content (loadScene / loadSceneFromMemory do), or touch external files.
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace nimbus::assets {

struct GltfFile {
    nlohmann::json json;                  // the whole glTF JSON
    std::vector<unsigned char> binChunk;  // the GLB BIN chunk (buffer 0 without a uri); empty for none
    bool binary = false;                  // read from a .glb container
};

// Throws InputError naming the file for a missing, truncated or malformed file, as loadScene does.
GltfFile readGltfFile(const std::filesystem::path& file);

// `binary`: a GLB container (JSON chunk space-padded, BIN chunk zero-padded to 4 bytes, omitted when
// empty). Otherwise the JSON as text, indented by 2; `binChunk` must then be empty.
std::vector<unsigned char> encodeGltf(const nlohmann::json& json, const std::vector<unsigned char>& binChunk, bool binary);

// The buffer and image URIs that name files (not data URIs), as written in the JSON.
std::vector<std::string> fileUris(const nlohmann::json& json);

// Where a relative URI of a file in `baseDirectory` points (percent escapes decoded, as the loader does).
std::filesystem::path resolveFileUri(const std::filesystem::path& baseDirectory, const std::string& uri);

// `bytes` as a base64 data URI of `mediaType` (e.g. "application/octet-stream").
std::string makeDataUri(const std::vector<unsigned char>& bytes, const std::string& mediaType);

}  // namespace nimbus::assets
