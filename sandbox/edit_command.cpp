// sandbox edit [SCENE] [--script FILE] [--viewport-size WxH] [--quality Q] [--mode M] [--set K=V]...
//                       [--budget-ms B]
// The level editor (sandbox/editor): a GLFW window with Dear ImGui. With --script it runs the
// commands of FILE in the live window and exits (non-zero on the first failing command).
#include <algorithm>
#include <string>
#include <vector>

#include "cli_options.h"
#include "commands.h"
#include "editor/editor_state.h"
#include "editor/script.h"
#include "editor/window/editor_app.h"
#include "nimbus/base/error.h"
#include "session.h"

namespace nimbus::sandbox {
namespace {

// The editor's tier unless --quality or --set quality= says: a viewport that keeps up.
constexpr char kEditorDefaultQuality[] = "fast";

struct EditOptions {
    std::string scene, script, viewportSize, quality, mode;
    std::vector<std::string> settings;
    std::string budgetMs;
};

int run(const EditOptions& o) {
    editor::EditorOptions options;
    options.scene = o.scene;
    if (!o.viewportSize.empty()) {
        glm::ivec2 size;
        parseSize(o.viewportSize, size.x, size.y, "--viewport-size");
        options.viewportSize = size;
    }
    const bool qualitySet = std::any_of(o.settings.begin(), o.settings.end(), [](const std::string& s) { return s.rfind("quality=", 0) == 0; });
    options.view = {o.quality.empty() && !qualitySet ? kEditorDefaultQuality : o.quality, o.mode, o.settings};
    if (!o.budgetMs.empty()) options.budgetMs = parsePositive(o.budgetMs, "--budget-ms", 1e6, "milliseconds per frame");
    if (!o.script.empty()) {
        // Refused before the window opens: a script's commands must not run on an empty scene
        // (the interactive editor stays up and shows why instead).
        (void)editor::readScript(o.script);
        if (!o.scene.empty()) editor::EditorState(options.view).open(o.scene);
    }
    editor::EditorApp app(options);
    return o.script.empty() ? app.run() : app.runScript(o.script);
}

}  // namespace

CommandRunner addEditCommand(CLI::App& app) {
    auto options = std::make_shared<EditOptions>();
    auto* cmd = app.add_subcommand("edit", "the level editor: a window with the live scene, panels, undo and reference snapshots");
    cmd->add_option("scene", options->scene, "glTF scene to open (.gltf or .glb)");
    cmd->add_option("--script", options->script, "run the editor commands of FILE, one per line, then exit (sandbox/editor/script.h)");
    cmd->add_option("--viewport-size", options->viewportSize, "render the viewport at WxH whatever the window size");
    cmd->add_option("--quality", options->quality, settingOptionHelp("quality", "the quality tier", kEditorDefaultQuality));
    cmd->add_option("--mode", options->mode, settingOptionHelp("mode", "how the medium is drawn", "the scene's, else particles"));
    cmd->add_option("--set", options->settings, "KEY=VALUE render setting (sandbox settings lists them)");
    cmd->add_option("--budget-ms", options->budgetMs, "walk the quality ladder until frames fit B ms");
    return [options] { return run(*options); };
}

}  // namespace nimbus::sandbox
