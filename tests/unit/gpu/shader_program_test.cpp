// Shader loading (gpu/shader_program.h): #include once per stage, cycles refused, defines injected
// after #version without shifting line numbers, and driver logs mapped back to file:line.
#include "nimbus/gpu/shader_program.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>

#include "gl_test_context.h"
#include "nimbus/base/error.h"
#include "nimbus/base/paths.h"

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

TEST(PreprocessShader, EveryEngineShaderResolves) {
    const std::filesystem::path folder = shaderDirectory();
    int stages = 0;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(folder)) {
        const std::string ext = entry.path().extension().string();
        if (ext != ".vert" && ext != ".frag" && ext != ".geom" && ext != ".comp") continue;
        const std::string file = std::filesystem::relative(entry.path(), folder).generic_string();
        EXPECT_NO_THROW(preprocessShader(folder, file, {})) << file;
        ++stages;
    }
    EXPECT_GE(stages, 6);  // opaque, shadow_depth, compose + fullscreen at least
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
