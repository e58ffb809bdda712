#pragma once
// Where Nimbus finds its own files (shaders, content) at run time.
#include <filesystem>

namespace nimbus {

// The shaders/ folder: $NIMBUS_SHADER_DIR if set, else the source tree this binary was built from.
std::filesystem::path shaderDirectory();

// The source tree this binary was built from ($NIMBUS_SOURCE_DIR if set): where tools/ lives.
std::filesystem::path sourceDirectory();

// The content/ folder: $NIMBUS_CONTENT_DIR if set, else the source tree's content/.
std::filesystem::path contentDirectory();

}  // namespace nimbus
