#include "gltf_container.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <string_view>

#include "nimbus/base/error.h"

namespace nimbus::assets {
namespace {

constexpr std::uint32_t kChunkJson = 0x4E4F534A;  // "JSON"
constexpr std::uint32_t kChunkBin = 0x004E4942;   // "BIN\0"
// tinygltf takes sizes as 32-bit unsigned, and the GLB length field is 32 bits.
constexpr std::uintmax_t kMaxFileBytes = std::numeric_limits<std::uint32_t>::max();

std::uint32_t readU32(const std::vector<unsigned char>& bytes, std::size_t offset) {
    // GLB is little-endian, like every machine we build for.
    std::uint32_t v = 0;
    std::memcpy(&v, bytes.data() + offset, 4);
    return v;
}

std::string hex(std::uint32_t v) {
    static const char* digits = "0123456789ABCDEF";
    std::string out = "0x";
    for (int shift = 28; shift >= 0; shift -= 4) out += digits[(v >> shift) & 0xF];
    return out;
}

void splitGlb(GltfSource& src, const std::string& name) {
    const std::size_t size = src.bytes.size();
    auto fail = [&](const std::string& field, const std::string& problem) {
        throwInputError(name, "GLB container", field, problem);
    };
    if (size < 20) fail("header", "truncated: " + std::to_string(size) + " bytes, a GLB needs at least 20");
    const std::uint32_t version = readU32(src.bytes, 4);
    const std::uint32_t length = readU32(src.bytes, 8);
    if (version != 2) fail("version", "GLB version " + std::to_string(version) + " is not supported (only 2)");
    if (length > size)
        fail("length", "truncated: the header says " + std::to_string(length) + " bytes but the file has " +
                           std::to_string(size));
    if (length < size)
        fail("length", "the header says " + std::to_string(length) + " bytes but the file has " +
                           std::to_string(size) + " (trailing data)");

    const std::uint64_t jsonLength = readU32(src.bytes, 12);
    const std::uint32_t jsonType = readU32(src.bytes, 16);
    if (jsonType != kChunkJson) fail("chunks[0].type", "first chunk has type " + hex(jsonType) + ", expected JSON");
    if (jsonLength == 0) fail("chunks[0].length", "the JSON chunk is empty");
    if (20 + jsonLength > length)
        fail("chunks[0].length", "truncated: the JSON chunk claims " + std::to_string(jsonLength) +
                                     " bytes but only " + std::to_string(length - 20) + " follow");
    src.jsonOffset = 20;
    src.jsonSize = static_cast<std::size_t>(jsonLength);

    const std::uint64_t binStart = 20 + jsonLength;
    if (binStart == length) return;  // no BIN chunk
    if (binStart + 8 > length)
        fail("chunks[1]", "truncated: " + std::to_string(length - binStart) + " bytes after the JSON chunk, a chunk header needs 8");
    const std::uint64_t binLength = readU32(src.bytes, static_cast<std::size_t>(binStart));
    const std::uint32_t binType = readU32(src.bytes, static_cast<std::size_t>(binStart + 4));
    if (binType != kChunkBin) fail("chunks[1].type", "second chunk has type " + hex(binType) + ", expected BIN");
    if (binStart + 8 + binLength > length)
        fail("chunks[1].length", "truncated: the BIN chunk claims " + std::to_string(binLength) + " bytes but only " +
                                     std::to_string(length - binStart - 8) + " follow");
    if (binLength == 0 || binLength % 4 != 0)
        fail("chunks[1].length", "the BIN chunk length " + std::to_string(binLength) +
                                     " is not a positive multiple of 4 (GLB chunks are 4-byte padded)");
    // Chunks after BIN have unknown types, which the GLB spec says to ignore.
    src.binChunkSize = static_cast<std::size_t>(binLength);
}

// nlohmann's what() starts with "[json.exception.parse_error.101] "; the rest is the useful part.
// Syntax errors say where they are; a number too large for a double ("1e400") does not, so its
// token is looked up in the text to give the line.
std::string describeJsonError(const nlohmann::json::exception& e, const char* text, std::size_t size) {
    std::string what = e.what();
    if (const auto close = what.find("] "); what.rfind("[json.exception", 0) == 0 && close != std::string::npos)
        what = what.substr(close + 2);
    // "last read: '...'" quotes raw input bytes, which may be binary in a damaged file.
    for (char& c : what)
        if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7F) c = '?';
    if (what.find(" line ") != std::string::npos) return what;
    const auto open = what.find("parsing '");
    const auto end = open == std::string::npos ? std::string::npos : what.find('\'', open + 9);
    if (end == std::string::npos) return what;
    const std::string token = what.substr(open + 9, end - open - 9);
    const std::string_view body(text, size);
    const auto at = body.find(token);
    if (token.empty() || at == std::string_view::npos) return what;
    const std::size_t line = 1 + static_cast<std::size_t>(std::count(body.begin(), body.begin() + static_cast<std::ptrdiff_t>(at), '\n'));
    return what + " at line " + std::to_string(line);
}

}  // namespace

GltfSource readGltfSource(const std::filesystem::path& file, const std::string& name) {
    std::error_code ec;
    const auto status = std::filesystem::status(file, ec);
    if (ec || !std::filesystem::exists(status)) throwInputError(name, "", "", "no such file");
    if (std::filesystem::is_directory(status)) throwInputError(name, "", "", "is a directory, not a glTF file");
    const std::uintmax_t fileSize = std::filesystem::file_size(file, ec);
    if (ec) throwInputError(name, "", "", "cannot read the file size: " + ec.message());
    if (fileSize == 0) throwInputError(name, "", "", "the file is empty");
    if (fileSize > kMaxFileBytes) throwInputError(name, "", "", "files of 4 GiB or more are not supported");

    std::vector<unsigned char> bytes(static_cast<std::size_t>(fileSize));
    std::ifstream in(file, std::ios::binary);
    if (!in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(bytes.size())))
        throwInputError(name, "", "", "cannot read the file");
    return parseGltfBytes(std::move(bytes), name);
}

GltfSource parseGltfBytes(std::vector<unsigned char> bytes, const std::string& name) {
    if (bytes.empty()) throwInputError(name, "", "", "the file is empty");
    if (bytes.size() > kMaxFileBytes) throwInputError(name, "", "", "files of 4 GiB or more are not supported");
    GltfSource src;
    src.bytes = std::move(bytes);
    src.binary = src.bytes.size() >= 4 && std::memcmp(src.bytes.data(), "glTF", 4) == 0;
    if (src.binary) {
        splitGlb(src, name);
    } else {
        src.jsonOffset = 0;
        src.jsonSize = src.bytes.size();
    }

    const char* text = reinterpret_cast<const char*>(src.bytes.data() + src.jsonOffset);
    try {
        src.json = nlohmann::json::parse(text, text + src.jsonSize);
    } catch (const nlohmann::json::exception& e) {
        throwInputError(name, src.binary ? "GLB JSON chunk" : "JSON", "", "malformed JSON: " + describeJsonError(e, text, src.jsonSize));
    }
    if (!src.json.is_object()) throwInputError(name, "JSON", "", "the top level must be a JSON object");
    return src;
}

}  // namespace nimbus::assets
