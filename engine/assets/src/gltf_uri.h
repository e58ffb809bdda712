#pragma once
// glTF URIs: embedded base64 data ("data:...;base64,...") or paths relative to the glTF file,
// possibly percent-encoded ("2x2%20image.png"). Used to check buffers and images before tinygltf
// reads them, so a missing file or a bad data URI is refused with our one-line message.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>

namespace nimbus::assets {

bool isDataUri(const std::string& uri);

// The media type of a data URI ("image/png"), without parameters.
std::string dataUriMediaType(const std::string& uri);

// Whether tinygltf decodes this data URI (it knows a fixed list of media types, base64 only).
bool isDecodableDataUri(const std::string& uri);

// Decoded byte count of a base64 data URI, or the reason it is not valid base64.
struct DataUriSize {
    std::optional<std::size_t> bytes;
    std::string problem;
};
DataUriSize dataUriDecodedSize(const std::string& uri);

// A '%' not followed by two hex digits (tinygltf would decode it to a NUL byte).
bool hasMalformedPercentEscape(const std::string& uri);

// A relative URI as a file path, decoded the way tinygltf decodes it (%XX escapes; '+' is a space).
std::string decodeUriPath(const std::string& uri);

// Where tinygltf will look for a relative URI of the file in `baseDirectory`.
std::filesystem::path resolveUri(const std::filesystem::path& baseDirectory, const std::string& uri);

}  // namespace nimbus::assets
