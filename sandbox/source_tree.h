#pragma once
// The source tree the sandbox was built from, where tools/ lives (bench's plots).
//
// Does not: serve the engine or the plugin, which read nothing of the source tree at run time
// (shaders are built in: nimbus/gpu/builtin_shaders.h).
#include <filesystem>

namespace nimbus::sandbox {

// $NIMBUS_SOURCE_DIR if set, else the folder this binary was configured from.
std::filesystem::path sourceDirectory();

}  // namespace nimbus::sandbox
