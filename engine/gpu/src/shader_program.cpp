#include "nimbus/gpu/shader_program.h"

#include <cstdlib>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "nimbus/base/error.h"
#include "nimbus/gpu/builtin_shaders.h"

namespace nimbus::gpu {
namespace {

std::string readFile(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw SystemError("shader file not found: " + path.string());
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// The folder that stands in for the built-in shaders, when $NIMBUS_SHADER_DIR names one.
std::filesystem::path overrideFolder() {
    const char* value = std::getenv("NIMBUS_SHADER_DIR");
    return value != nullptr ? std::filesystem::path(value) : std::filesystem::path();
}

struct Preprocessor {
    // Searched in order; an empty path is the built-in shaders (or $NIMBUS_SHADER_DIR in their place).
    std::vector<std::filesystem::path> folders;
    PreprocessedSource out;
    std::set<std::string> included;
    std::vector<std::string> stack;

    // The first folder that has `file`.
    std::string read(const std::string& file) const {
        const std::filesystem::path replacement = overrideFolder();
        std::string searched;
        for (const auto& entry : folders) {
            const std::filesystem::path folder = entry.empty() ? replacement : entry;
            if (!searched.empty()) searched.append(", ");
            if (folder.empty()) {
                if (const BuiltInShader* shader = builtInShader(file)) return std::string(shader->text);
                searched.append("the built-in shaders");
                continue;
            }
            if (std::filesystem::exists(folder / file)) return readFile(folder / file);
            searched.append(folder.string());
        }
        throw SystemError("shader file not found: " + file + " (searched " + searched + ")");
    }

    void expand(const std::string& file, const std::vector<std::string>* defines) {
        for (const auto& open : stack)
            if (open == file) throw SystemError("shader include cycle through " + file);
        if (!included.insert(file).second) return;  // include once per stage
        stack.push_back(file);
        const int index = static_cast<int>(out.files.size());
        out.files.push_back(file);

        std::istringstream lines(read(file));
        static const std::regex includeLine(R"(^\s*#\s*include\s+"([^"]+)\"\s*$)");
        std::string line;
        int number = 0;
        bool versionSeen = defines == nullptr;
        if (defines == nullptr) out.text += "#line 1 " + std::to_string(index) + "\n";
        while (std::getline(lines, line)) {
            ++number;
            std::smatch match;
            if (!versionSeen && line.rfind("#version", 0) == 0) {
                out.text += line + "\n";
                for (const auto& define : *defines) out.text += "#define " + define + "\n";
                out.text += "#line " + std::to_string(number + 1) + " " + std::to_string(index) + "\n";
                versionSeen = true;
            } else if (std::regex_match(line, match, includeLine)) {
                expand(match[1].str(), nullptr);
                out.text += "#line " + std::to_string(number + 1) + " " + std::to_string(index) + "\n";
            } else {
                out.text += line + "\n";
            }
        }
        if (!versionSeen) throw SystemError("shader " + file + " has no #version line");
        stack.pop_back();
    }
};

Shader compileStage(GLenum type, const ProgramDesc& desc, const std::filesystem::path& folder, const std::string& file,
                    std::string& errors) {
    PreprocessedSource source = preprocessShader(folder, file, desc.defines, desc.includePath);
    Shader shader(glCreateShader(type));
    const char* text = source.text.c_str();
    glShaderSource(shader.id(), 1, &text, nullptr);
    glCompileShader(shader.id());
    GLint ok = GL_FALSE;
    glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
    if (!ok) {
        GLint length = 0;
        glGetShaderiv(shader.id(), GL_INFO_LOG_LENGTH, &length);
        std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
        glGetShaderInfoLog(shader.id(), length, nullptr, log.data());
        errors += mapShaderLog(log.c_str(), source.files);
    }
    return shader;
}

}  // namespace

PreprocessedSource preprocessShader(const std::filesystem::path& folder, const std::string& file,
                                    const std::vector<std::string>& defines, const std::vector<std::filesystem::path>& includePath) {
    // A program's own folder, then its include path, then the built-in shaders (a host's shader
    // includes the plugin's files with no folder of Nimbus's on disk).
    Preprocessor pre{{folder}, {}, {}, {}};
    pre.folders.insert(pre.folders.end(), includePath.begin(), includePath.end());
    if (!folder.empty()) pre.folders.emplace_back();
    pre.expand(file, &defines);
    return pre.out;
}

std::string mapShaderLog(const std::string& log, const std::vector<std::string>& files) {
    // Mesa writes "SOURCE:LINE(COL): ..."; NVIDIA writes "SOURCE(LINE) : ...". Map both.
    static const std::regex mesa(R"(^(\d+):(\d+)\((\d+)\)(.*)$)");
    static const std::regex nvidia(R"(^(\d+)\((\d+)\)(.*)$)");
    std::istringstream lines(log);
    std::string line, out;
    while (std::getline(lines, line)) {
        std::smatch m;
        auto fileName = [&](const std::string& index) {
            const std::size_t i = std::stoul(index);
            return i < files.size() ? files[i] : "source " + index;
        };
        if (std::regex_match(line, m, mesa))
            out += fileName(m[1]) + ":" + m[2].str() + "(" + m[3].str() + ")" + m[4].str() + "\n";
        else if (std::regex_match(line, m, nvidia))
            out += fileName(m[1]) + ":" + m[2].str() + m[3].str() + "\n";
        else if (!line.empty())
            out += line + "\n";
    }
    return out;
}

Program compileProgram(const ProgramDesc& desc) {
    const std::filesystem::path& folder = desc.folder;
    std::string errors;
    std::vector<Shader> stages;
    const std::pair<GLenum, const std::string*> wanted[] = {{GL_VERTEX_SHADER, &desc.vertex},
                                                            {GL_GEOMETRY_SHADER, &desc.geometry},
                                                            {GL_FRAGMENT_SHADER, &desc.fragment},
                                                            {GL_COMPUTE_SHADER, &desc.compute}};
    std::string names;
    for (const auto& [type, file] : wanted) {
        if (file->empty()) continue;
        stages.push_back(compileStage(type, desc, folder, *file, errors));
        names += (names.empty() ? "" : "+") + *file;
    }
    if (stages.empty()) throw SystemError("shader program with no stages");
    if (!errors.empty()) throw SystemError("shader compile failed (" + names + "):\n" + errors);

    Program program(glCreateProgram());
    for (const auto& s : stages) glAttachShader(program.id(), s.id());
    glLinkProgram(program.id());
    GLint ok = GL_FALSE;
    glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
    for (const auto& s : stages) glDetachShader(program.id(), s.id());
    if (!ok) {
        GLint length = 0;
        glGetProgramiv(program.id(), GL_INFO_LOG_LENGTH, &length);
        std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
        glGetProgramInfoLog(program.id(), length, nullptr, log.data());
        throw SystemError("shader link failed (" + names + "):\n" + std::string(log.c_str()));
    }
    return program;
}

}  // namespace nimbus::gpu
