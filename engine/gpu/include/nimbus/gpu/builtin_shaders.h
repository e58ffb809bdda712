#pragma once
// The shaders this library was built with: every file of Nimbus's shaders/ folder, compiled into
// nimbus_gpu (cmake/EmbedShaders.cmake), so a program needs no shader folder at run time and an
// installed plugin works wherever it is installed. compileProgram reads them unless
// $NIMBUS_SHADER_DIR names a folder to read instead (shader work without a rebuild).
//
// Does not: hold a host's own shaders (they come from ProgramDesc::folder).
#include <cstddef>
#include <span>
#include <string_view>

namespace nimbus::gpu {

struct BuiltInShader {
    std::string_view path;  // relative to shaders/, with '/': "media/host/light_transmittance.glsl"
    std::string_view text;
};

// The file at `path`, or nullptr when it was not built in.
const BuiltInShader* builtInShader(std::string_view path);
// Every built-in file, sorted by path.
std::span<const BuiltInShader> builtInShaders();

namespace detail {
extern const BuiltInShader kBuiltInShaders[];
extern const std::size_t kBuiltInShaderCount;
}  // namespace detail

}  // namespace nimbus::gpu
