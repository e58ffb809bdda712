#include "script.h"

#include <gtest/gtest.h>

#include <fstream>

#include "nimbus/base/error.h"

namespace nimbus::sandbox::editor {
namespace {

namespace fs = std::filesystem;
const fs::path kContent = NIMBUS_CONTENT_DIR_FOR_TESTS;

// Records the window-side commands; the state is real.
class FakeTarget final : public ScriptTarget {
public:
    EditorState& state() override { return state_; }
    void renderFrames(int count) override { calls.push_back("frames " + std::to_string(count)); }
    void play(double seconds) override { calls.push_back("play " + std::to_string(seconds)); }
    void screenshot(const fs::path& file) override { calls.push_back("screenshot " + file.string()); }
    void writeViewport(const fs::path& file) override { calls.push_back("viewport " + file.string()); }
    void reference(const fs::path& file) override { calls.push_back("reference " + file.string()); }
    void viewThrough(const std::string& camera) override { calls.push_back("camera " + camera); }
    void quit() override { calls.push_back("quit"); }
    std::vector<std::string> calls;

private:
    EditorState state_;
};

void run(FakeTarget& target, const std::string& line) { runScriptLine(target, "test.txt", {7, line}); }

TEST(Script, CommandsReachTheStateAndTheWindow) {
    FakeTarget t;
    run(t, "open " + (kContent / "scenes/smoke.gltf").string());
    run(t, "select chimney");
    run(t, "set extensions.NIMBUS_participating_media.medium.extinction 7.5");
    run(t, "set translation [-2.0, 2.0, 0.3]");
    run(t, "add cloud fluff");
    run(t, "undo");
    run(t, "redo");
    run(t, "frames 3");
    run(t, "viewport out.exr");
    run(t, "reference");
    run(t, "quit");
    const Json& json = t.state().json();
    EXPECT_EQ(getField(json, findNode(json, "chimney"), "extensions.NIMBUS_participating_media.medium.extinction"), 7.5);
    EXPECT_EQ(getField(json, findNode(json, "chimney"), "translation"), Json::array({-2.0, 2.0, 0.3}));
    EXPECT_GE(findNode(json, "fluff"), 0);
    EXPECT_EQ(t.calls, (std::vector<std::string>{"frames 3", "viewport out.exr", "reference ", "quit"}));
}

TEST(Script, FailuresNameTheLineAndTheReason) {
    FakeTarget t;
    const auto message = [&](const std::string& line) -> std::string {
        try {
            run(t, line);
        } catch (const InputError& e) {
            return e.what();
        }
        return "(accepted)";
    };
    EXPECT_NE(message("fly away").find("test.txt:7: fly: unknown command"), std::string::npos);
    EXPECT_NE(message("select nobody").find("no node is named 'nobody'"), std::string::npos);
    EXPECT_NE(message("set name").find("usage: set PATH JSON_VALUE"), std::string::npos);
    EXPECT_NE(message("delete").find("no node is selected"), std::string::npos);
    EXPECT_NE(message("add teapot t").find("'teapot' is not one of"), std::string::npos);
    EXPECT_NE(message("frames 0").find("1..100000"), std::string::npos);
    EXPECT_NE(message("undo").find("nothing to undo"), std::string::npos);
    EXPECT_NE(message("time soon").find("'soon' is not a number"), std::string::npos);
    run(t, "open " + (kContent / "scenes/smoke.gltf").string());
    run(t, "select chimney");
    EXPECT_NE(message("set translation [1, 2").find("is not a JSON value"), std::string::npos);
    EXPECT_TRUE(t.calls.empty());
}

TEST(Script, ReadSkipsBlankLinesAndComments) {
    const fs::path file = fs::temp_directory_path() / "nimbus_script_test.txt";
    std::ofstream(file) << "# a comment\n\nselect chimney\n  frames 2  \n";
    const auto lines = readScript(file);
    ASSERT_EQ(lines.size(), 2u);
    EXPECT_EQ(lines[0].number, 3);
    EXPECT_EQ(lines[1].text, "frames 2");
    EXPECT_THROW(readScript(file.string() + ".missing"), InputError);
}

}  // namespace
}  // namespace nimbus::sandbox::editor
