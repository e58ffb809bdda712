#include "nimbus/gpu/builtin_shaders.h"

#include <algorithm>

namespace nimbus::gpu {

std::span<const BuiltInShader> builtInShaders() { return {detail::kBuiltInShaders, detail::kBuiltInShaderCount}; }

const BuiltInShader* builtInShader(std::string_view path) {
    const auto all = builtInShaders();
    const auto it = std::lower_bound(all.begin(), all.end(), path,
                                     [](const BuiltInShader& s, std::string_view p) { return s.path < p; });
    return it != all.end() && it->path == path ? &*it : nullptr;
}

}  // namespace nimbus::gpu
