#include "nimbus/assets/gltf_file.h"

#include <cstdint>
#include <cstring>
#include <stdexcept>

#include <OpenImageIO/strutil.h>

#include "gltf_container.h"
#include "gltf_uri.h"

namespace nimbus::assets {
namespace {

void appendU32(std::vector<unsigned char>& out, std::uint32_t v) {
    const auto at = out.size();
    out.resize(at + 4);
    std::memcpy(out.data() + at, &v, 4);  // GLB is little-endian, like every machine we build for
}

void appendChunk(std::vector<unsigned char>& out, std::uint32_t type, const unsigned char* data, std::size_t size,
                 unsigned char pad) {
    const std::size_t padded = (size + 3) / 4 * 4;
    appendU32(out, static_cast<std::uint32_t>(padded));
    appendU32(out, type);
    out.insert(out.end(), data, data + size);
    out.insert(out.end(), padded - size, pad);
}

}  // namespace

GltfFile readGltfFile(const std::filesystem::path& file) {
    GltfSource src = readGltfSource(file, file.string());
    GltfFile out;
    out.json = std::move(src.json);
    out.binary = src.binary;
    if (src.binChunkSize) {
        const auto begin = src.bytes.begin() + static_cast<std::ptrdiff_t>(src.jsonOffset + src.jsonSize + 8);
        out.binChunk.assign(begin, begin + static_cast<std::ptrdiff_t>(*src.binChunkSize));
    }
    return out;
}

std::vector<unsigned char> encodeGltf(const nlohmann::json& json, const std::vector<unsigned char>& binChunk, bool binary) {
    const std::string text = binary ? json.dump() : json.dump(2) + "\n";
    if (!binary) {
        if (!binChunk.empty()) throw std::invalid_argument("encodeGltf: a .gltf text file cannot hold a BIN chunk");
        return {text.begin(), text.end()};
    }
    std::vector<unsigned char> out;
    appendU32(out, 0x46546C67);  // "glTF"
    appendU32(out, 2);
    appendU32(out, 0);  // total length, patched below
    appendChunk(out, 0x4E4F534A, reinterpret_cast<const unsigned char*>(text.data()), text.size(), ' ');
    if (!binChunk.empty()) appendChunk(out, 0x004E4942, binChunk.data(), binChunk.size(), 0);
    const auto length = static_cast<std::uint32_t>(out.size());
    std::memcpy(out.data() + 8, &length, 4);
    return out;
}

std::vector<std::string> fileUris(const nlohmann::json& json) {
    std::vector<std::string> uris;
    for (const char* array : {"buffers", "images"}) {
        if (!json.contains(array) || !json[array].is_array()) continue;
        for (const auto& item : json[array])
            if (item.is_object() && item.contains("uri") && item["uri"].is_string() && !isDataUri(item["uri"].get<std::string>()))
                uris.push_back(item["uri"].get<std::string>());
    }
    return uris;
}

std::filesystem::path resolveFileUri(const std::filesystem::path& baseDirectory, const std::string& uri) {
    return resolveUri(baseDirectory, uri);
}

std::string makeDataUri(const std::vector<unsigned char>& bytes, const std::string& mediaType) {
    const std::string raw(bytes.begin(), bytes.end());
    return "data:" + mediaType + ";base64," + OIIO::Strutil::base64_encode(raw);
}

}  // namespace nimbus::assets
