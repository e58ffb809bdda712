// Shader loading (gpu/shader_program.h): #include once per stage, cycles refused, defines injected
// after #version without shifting line numbers, driver logs mapped back to file:line, and the
// built-in shaders the same files as the source tree's shaders/ folder.
#include "nimbus/gpu/shader_program.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>

#include "gl_test_context.h"
#include "nimbus/base/error.h"
#include "nimbus/gpu/builtin_shaders.h"

namespace nimbus::gpu {
namespace {

using test::GlTest;

// tests/data/shader_fixtures/<case>: the stages each test loads (README.md there).
std::filesystem::path fixture(const std::string& name) {
    return std::filesystem::path(NIMBUS_TEST_DATA_DIR) / "shader_fixtures" / name;
}

// The preprocessed text a fixture stage must give, stored beside it as <stage>.expected.
std::string expectedText(const std::filesystem::path& folder, const std::string& stage) {
    std::ifstream in(folder / (stage + ".expected"), std::ios::binary);
    EXPECT_TRUE(in) << "missing " << (folder / (stage + ".expected"));
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

std::string messageOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const SystemError& e) {
        return e.what();
    }
    ADD_FAILURE() << "no SystemError thrown";
    return {};
}

TEST(PreprocessShader, InsertsDefinesAfterVersionAndKeepsLineNumbers) {
    const PreprocessedSource s = preprocessShader(fixture("defines"), "main.frag", {"FOO", "BAR 2"});
    EXPECT_EQ(s.text, expectedText(fixture("defines"), "main.frag"));
    EXPECT_EQ(s.files, std::vector<std::string>{"main.frag"});
}

TEST(PreprocessShader, IncludesEachFileOncePerStage) {
    const PreprocessedSource s = preprocessShader(fixture("include_once"), "main.frag", {});
    EXPECT_EQ(s.files, (std::vector<std::string>{"main.frag", "a.glsl", "b.glsl"}));
    // a.glsl appears once though b.glsl includes it again; each included file starts at its own
    // line 1 and the includer resumes at the line after the #include.
    EXPECT_EQ(s.text, expectedText(fixture("include_once"), "main.frag"));
}

TEST(PreprocessShader, IncludePathsAreRelativeToTheShaderFolder) {
    const PreprocessedSource s = preprocessShader(fixture("relative"), "media/particles.frag", {});
    EXPECT_EQ(s.files, (std::vector<std::string>{"media/particles.frag", "common/math.glsl"}));
    EXPECT_EQ(s.text, expectedText(fixture("relative"), "media/particles.frag"));
}

TEST(PreprocessShader, RefusesIncludeCycles) {
    const std::string message = messageOf([&] { preprocessShader(fixture("cycle"), "main.frag", {}); });
    EXPECT_NE(message.find("cycle"), std::string::npos) << message;
    EXPECT_NE(message.find("a.glsl"), std::string::npos) << message;
}

TEST(PreprocessShader, RefusesAFileIncludingItself) {
    EXPECT_THROW(preprocessShader(fixture("self"), "main.frag", {}), SystemError);
}

TEST(PreprocessShader, RefusesMissingFilesAndMissingVersion) {
    std::string message = messageOf([&] { preprocessShader(fixture("missing"), "main.frag", {}); });
    EXPECT_NE(message.find("nowhere.glsl"), std::string::npos) << message;
    message = messageOf([&] { preprocessShader(fixture("missing"), "plain.frag", {}); });
    EXPECT_NE(message.find("#version"), std::string::npos) << message;
    message = messageOf([&] { preprocessShader(fixture("missing"), "absent.vert", {}); });
    EXPECT_NE(message.find("absent.vert"), std::string::npos) << message;
}

// The source tree's shaders/, which the library builds in.
const std::filesystem::path kShaderSources = std::filesystem::path(NIMBUS_CONTENT_DIR_FOR_TESTS).parent_path() / "shaders";

std::string fileText(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

TEST(PreprocessShader, EveryEngineShaderResolves) {
    int stages = 0;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(kShaderSources)) {
        const std::string ext = entry.path().extension().string();
        if (ext != ".vert" && ext != ".frag" && ext != ".geom" && ext != ".comp") continue;
        const std::string file = std::filesystem::relative(entry.path(), kShaderSources).generic_string();
        EXPECT_NO_THROW(preprocessShader(kShaderSources, file, {})) << file;
        EXPECT_NO_THROW(preprocessShader({}, file, {})) << file << " (built in)";
        ++stages;
    }
    EXPECT_GE(stages, 6);  // opaque, shadow_depth, compose + fullscreen at least
}

// Every file of shaders/ is built in as it is on disk, and nothing else: the build regenerates the table.
TEST(BuiltInShaders, AreTheSourceTreesShadersByteForByte) {
    std::vector<std::string> onDisk;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(kShaderSources))
        if (entry.is_regular_file()) onDisk.push_back(std::filesystem::relative(entry.path(), kShaderSources).generic_string());
    std::sort(onDisk.begin(), onDisk.end());
    std::vector<std::string> builtIn;
    for (const BuiltInShader& shader : builtInShaders()) builtIn.emplace_back(shader.path);
    EXPECT_TRUE(std::is_sorted(builtIn.begin(), builtIn.end()));
    EXPECT_EQ(builtIn, onDisk);
    for (const std::string& file : onDisk) {
        const BuiltInShader* shader = builtInShader(file);
        ASSERT_NE(shader, nullptr) << file;
        EXPECT_EQ(shader->text, fileText(kShaderSources / file)) << file;
    }
    EXPECT_EQ(builtInShader("media/absent.glsl"), nullptr);
}

// A host's own folder comes first, then its include path, then the built-in shaders: its shader
// includes the plugin's host include with no folder of Nimbus's on disk.
TEST(PreprocessShader, AHostsShaderIncludesTheBuiltInPluginFiles) {
    const PreprocessedSource source = preprocessShader(fixture("host_include"), "host.frag", {"MEDIA_LIGHT_TRANSMITTANCE"});
    EXPECT_NE(std::find(source.files.begin(), source.files.end(), "media/host/light_transmittance.glsl"), source.files.end());
    EXPECT_NE(source.text.find("mediaTransmittance"), std::string::npos);
    const std::string message = messageOf([&] { preprocessShader(fixture("host_include"), "absent.frag", {}); });
    EXPECT_NE(message.find("absent.frag (searched " + fixture("host_include").string() + ", the built-in shaders)"), std::string::npos)
        << message;
}

TEST(MapShaderLog, RewritesMesaSourceNumbersToFileNames) {
    const std::vector<std::string> files = {"opaque.frag", "common/lights.glsl"};
    EXPECT_EQ(mapShaderLog("0:12(5): error: `foo' undeclared\n1:3(10): error: syntax error\n", files),
              "opaque.frag:12(5): error: `foo' undeclared\ncommon/lights.glsl:3(10): error: syntax error\n");
}

TEST(MapShaderLog, RewritesNvidiaStyleAndKeepsOtherLines) {
    const std::vector<std::string> files = {"opaque.frag"};
    EXPECT_EQ(mapShaderLog("0(7) : error C1008: undefined variable \"x\"\n\nlink status: failed\n", files),
              "opaque.frag:7 : error C1008: undefined variable \"x\"\nlink status: failed\n");
}

TEST(MapShaderLog, NamesUnknownSourceNumbers) {
    EXPECT_EQ(mapShaderLog("4:2(1): error: x\n", {"only.frag"}), "source 4:2(1): error: x\n");
}

// ---- with a real context ----

class CompileProgram : public GlTest {};

TEST_F(CompileProgram, BuildsAValidProgram) {
    const Program p = compileProgram({.vertex = "ok.vert", .geometry = "", .fragment = "ok.frag", .compute = "",
                                      .defines = {"VALUE 2.0"}, .folder = fixture("compile")});
    ASSERT_TRUE(p);
    EXPECT_EQ(glIsProgram(p.id()), GL_TRUE);
    GLint linked = GL_FALSE;
    glGetProgramiv(p.id(), GL_LINK_STATUS, &linked);
    EXPECT_EQ(linked, GL_TRUE);
    EXPECT_EQ(context().takeGlErrors().count, 0u);
}

TEST_F(CompileProgram, ReportsTheIncludedFileAndLineOfAnError) {
    const std::string message = messageOf([&] {
        compileProgram({.vertex = "ok.vert", .geometry = "", .fragment = "include_error.frag", .compute = "", .defines = {},
                        .folder = fixture("compile")});
    });
    EXPECT_NE(message.find("broken_lib.glsl:4"), std::string::npos) << message;
    EXPECT_NE(message.find("undefined_thing"), std::string::npos) << message;
    EXPECT_NE(message.find("include_error.frag"), std::string::npos) << "the program is named: " << message;
}

TEST_F(CompileProgram, DefinesDoNotShiftTheReportedLine) {
    const std::string message = messageOf([&] {
        compileProgram({.vertex = "ok.vert", .geometry = "", .fragment = "bad_line.frag", .compute = "",
                        .defines = {"A 1", "B 2", "C"}, .folder = fixture("compile")});
    });
    EXPECT_NE(message.find("bad_line.frag:4"), std::string::npos) << message;
    EXPECT_EQ(message.find("0:"), std::string::npos) << "raw source numbers left in: " << message;
}

TEST_F(CompileProgram, ReportsLinkErrors) {
    const std::string message = messageOf([&] {
        compileProgram({.vertex = "ok.vert", .geometry = "", .fragment = "needs_input.frag", .compute = "", .defines = {},
                        .folder = fixture("compile")});
    });
    EXPECT_NE(message.find("link"), std::string::npos) << message;
    EXPECT_NE(message.find("vMissing"), std::string::npos) << message;
}

TEST_F(CompileProgram, RefusesAProgramWithoutStages) {
    EXPECT_THROW(compileProgram({.vertex = "", .geometry = "", .fragment = "", .compute = "", .defines = {}, .folder = fixture("compile")}),
                 SystemError);
}

}  // namespace
}  // namespace nimbus::gpu
