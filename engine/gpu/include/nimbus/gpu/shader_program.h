#pragma once
// GLSL programs built from Nimbus's shaders (built into the library: builtin_shaders.h) or a host's
// own folder. Sources may `#include "path.glsl"` (relative to the shaders folder, each file included
// once per stage); compile errors are reported as file:line with the original file names.
//
// Does not: cache binaries, or hot-reload (the editor may add that later).
#include <filesystem>
#include <string>
#include <vector>

#include "nimbus/gpu/gl_objects.h"

namespace nimbus::gpu {

struct ProgramDesc {
    std::string vertex;    // file names relative to the shader folder; empty = stage absent
    std::string geometry;
    std::string fragment;
    std::string compute;
    std::vector<std::string> defines;  // "NAME" or "NAME VALUE", inserted after #version
    // Empty: Nimbus's built-in shaders ($NIMBUS_SHADER_DIR instead when set).
    std::filesystem::path folder;
    // Further folders searched after `folder`, in order. The built-in shaders come last, so a host's
    // own shader includes the plugin's "media/host/..." files with nothing more.
    std::vector<std::filesystem::path> includePath;
};

// A preprocessed stage: the text GL compiles plus the files it came from (index = #line source number).
struct PreprocessedSource {
    std::string text;
    std::vector<std::string> files;
};

// Resolves #include and injects defines; throws nimbus::SystemError for a missing file or a cycle.
// `folder` as ProgramDesc::folder: empty is the built-in shaders, searched last otherwise.
PreprocessedSource preprocessShader(const std::filesystem::path& folder, const std::string& file,
                                    const std::vector<std::string>& defines,
                                    const std::vector<std::filesystem::path>& includePath = {});

// Rewrites a driver log ("0:12(5): error: ...") with file names ("opaque.frag:12(5): error: ...").
std::string mapShaderLog(const std::string& log, const std::vector<std::string>& files);

// Compiles and links; throws nimbus::SystemError listing every error with file:line.
Program compileProgram(const ProgramDesc& desc);

}  // namespace nimbus::gpu
