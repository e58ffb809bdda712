// The editor script's fuzz entry: the bytes as a script, run against the editor's model without
// a window.
#include <charconv>
#include <string>

#include "editor/editor_state.h"
#include "editor/script.h"
#include "fuzz_entries.h"
#include "nimbus/base/error.h"

namespace nimbus::fuzz {
namespace {

using sandbox::editor::EditorState;

// What a script needs beyond the state, with nothing drawn or written.
class HeadlessTarget final : public sandbox::editor::ScriptTarget {
public:
    EditorState& state() override { return state_; }
    void renderFrames(int) override {}
    void play(double seconds) override { state_.advance(seconds); }
    void screenshot(const std::filesystem::path&) override {}
    void writeViewport(const std::filesystem::path&) override {}
    void reference(const std::filesystem::path&) override {}
    void viewThrough(const std::string&) override {}
    void quit() override { quit_ = true; }
    bool quitting() const { return quit_; }

private:
    EditorState state_;
    bool quit_ = false;
};

// The lines the harness leaves out (fuzz_entries.h says why).
bool skipped(const std::string& line) {
    const auto space = line.find_first_of(" \t");
    const std::string command = line.substr(0, space);
    if (command == "open" || command == "save") return true;
    if (command != "time" && command != "play") return false;
    const std::string rest = space == std::string::npos ? "" : line.substr(line.find_first_not_of(" \t", space));
    double seconds = 0.0;
    const auto [end, ec] = std::from_chars(rest.data(), rest.data() + rest.size(), seconds);
    return ec == std::errc() && seconds > kScriptTimeLimit;
}

}  // namespace

void runEditorScript(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        HeadlessTarget target;
        target.state().open(NIMBUS_FUZZ_CONTENT_DIR "/scenes/smoke.gltf");
        for (const sandbox::editor::ScriptLine& line : sandbox::editor::parseScript(text)) {
            if (skipped(line.text)) continue;
            sandbox::editor::runScriptLine(target, "fuzz.script", line);
            if (target.quitting()) break;
        }
    } catch (const InputError&) {
        // The first refused line ends the script, as it ends `sandbox edit --script`.
    }
}

}  // namespace nimbus::fuzz
