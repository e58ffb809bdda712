#include "nimbus/base/paths.h"

#include <cstdlib>

namespace nimbus {
namespace {
std::filesystem::path fromEnvOr(const char* variable, const char* relative) {
    if (const char* value = std::getenv(variable); value != nullptr && *value != '\0') return value;
    return std::filesystem::path(NIMBUS_SOURCE_DIR) / relative;
}
}  // namespace

std::filesystem::path shaderDirectory() { return fromEnvOr("NIMBUS_SHADER_DIR", "shaders"); }
std::filesystem::path sourceDirectory() {
    if (const char* value = std::getenv("NIMBUS_SOURCE_DIR"); value != nullptr && *value != '\0') return value;
    return NIMBUS_SOURCE_DIR;
}
std::filesystem::path contentDirectory() { return fromEnvOr("NIMBUS_CONTENT_DIR", "content"); }

}  // namespace nimbus
