#include "gltf_uri.h"

#include <tiny_gltf.h>

namespace nimbus::assets {
namespace {

bool isBase64Char(char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '+' || c == '/';
}

int hexValue(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

}  // namespace

bool isDataUri(const std::string& uri) { return uri.rfind("data:", 0) == 0; }

std::string dataUriMediaType(const std::string& uri) {
    if (!isDataUri(uri)) return {};
    const std::size_t end = uri.find_first_of(";,", 5);
    return uri.substr(5, end == std::string::npos ? std::string::npos : end - 5);
}

bool isDecodableDataUri(const std::string& uri) { return tinygltf::IsDataURI(uri); }

DataUriSize dataUriDecodedSize(const std::string& uri) {
    const std::size_t comma = uri.find(',');
    if (comma == std::string::npos) return {std::nullopt, "data URI without ','"};
    if (comma < 7 || uri.compare(comma - 7, 7, ";base64") != 0) return {std::nullopt, "data URI is not base64-encoded"};
    // tinygltf's decoder stops at the first character that is not base64, so anything but trailing
    // '=' padding there would silently truncate the data: refuse it instead.
    std::size_t n = 0;
    std::size_t i = comma + 1;
    for (; i < uri.size() && isBase64Char(uri[i]); ++i) ++n;
    std::size_t padding = 0;
    for (; i < uri.size() && uri[i] == '='; ++i) ++padding;
    if (i != uri.size())
        return {std::nullopt, "invalid base64 character at offset " + std::to_string(i - comma - 1) + " of the data"};
    if (n % 4 == 1 || padding > 2) return {std::nullopt, "malformed base64 data (bad length or padding)"};
    const std::size_t bytes = n / 4 * 3 + (n % 4 == 2 ? 1 : n % 4 == 3 ? 2 : 0);
    return {bytes, {}};
}

bool hasMalformedPercentEscape(const std::string& uri) {
    for (std::size_t i = 0; i < uri.size(); ++i)
        if (uri[i] == '%' && (i + 2 >= uri.size() || hexValue(uri[i + 1]) < 0 || hexValue(uri[i + 2]) < 0)) return true;
    return false;
}

std::string decodeUriPath(const std::string& uri) {
    std::string out;
    out.reserve(uri.size());
    for (std::size_t i = 0; i < uri.size(); ++i) {
        const char c = uri[i];
        if (c == '+') {
            out += ' ';
        } else if (c == '%' && i + 2 < uri.size() && hexValue(uri[i + 1]) >= 0 && hexValue(uri[i + 2]) >= 0) {
            out += static_cast<char>(hexValue(uri[i + 1]) * 16 + hexValue(uri[i + 2]));
            i += 2;
        } else {
            out += c;
        }
    }
    return out;
}

std::filesystem::path resolveUri(const std::filesystem::path& baseDirectory, const std::string& uri) {
    return baseDirectory / decodeUriPath(uri);
}

}  // namespace nimbus::assets
