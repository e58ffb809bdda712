#include "source_tree.h"

#include <cstdlib>

namespace nimbus::sandbox {

std::filesystem::path sourceDirectory() {
    if (const char* value = std::getenv("NIMBUS_SOURCE_DIR"); value != nullptr && *value != '\0') return value;
    return NIMBUS_SOURCE_DIR;
}

}  // namespace nimbus::sandbox
