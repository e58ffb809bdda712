#pragma once
// `sandbox edit SCENE --script FILE`: one command per line, run in the live editor, for tests and
// automation. The command names are fixed (tools outside the project rely on them):
//   select NODE_NAME | set PATH JSON_VALUE | add emitter|cloud|light|box|camera NAME | delete | undo | redo
//   time SECONDS | quality fast|balanced|exact | mode M | frames N | screenshot FILE.png
//   viewport FILE.exr | reference [FILE.exr] | save FILE | quit
// and, beyond those: open FILE | duplicate | rename NAME | parent NODE_NAME|- | play SECONDS | camera NAME|-
// | memory (prints resident memory and the undo history's size)
// Blank lines and lines starting with '#' are skipped. A command that fails throws InputError with
// the reason; the editor's state is as it was before that command.
//
// Does not: branch, loop or define variables.
#include <filesystem>
#include <string>
#include <vector>

#include "editor_state.h"

namespace nimbus::sandbox::editor {

// What a script needs from the running editor beyond its state: frames, images and snapshots.
class ScriptTarget {
public:
    virtual ~ScriptTarget() = default;
    virtual EditorState& state() = 0;
    virtual void renderFrames(int count) = 0;                         // UI and viewport, as shown
    virtual void play(double seconds) = 0;                            // as the Play button does
    virtual void screenshot(const std::filesystem::path& file) = 0;   // the whole window
    virtual void writeViewport(const std::filesystem::path& file) = 0;  // linear viewport image
    virtual void reference(const std::filesystem::path& file) = 0;    // snapshot, waited for; empty: not written
    virtual void viewThrough(const std::string& camera) = 0;          // "-": the free orbit camera
    virtual void quit() = 0;
};

struct ScriptLine {
    int number = 0;  // 1-based, for messages
    std::string text;
};

// Reads the file (InputError when it cannot) into its command lines.
std::vector<ScriptLine> readScript(const std::filesystem::path& file);
// The same for a script's text.
std::vector<ScriptLine> parseScript(const std::string& text);

// Runs one command. Throws InputError naming the script line for anything wrong.
void runScriptLine(ScriptTarget& target, const std::filesystem::path& script, const ScriptLine& line);

}  // namespace nimbus::sandbox::editor
