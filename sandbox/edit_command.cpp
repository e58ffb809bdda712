// sandbox edit [SCENE] [--script FILE] [--viewport-size WxH] [--quality Q] [--mode M] [--set K=V]...
//                       [--budget-ms B]
// The level editor (sandbox/editor): a GLFW window with Dear ImGui. With --script it runs the
// commands of FILE in the live window and exits (non-zero on the first failing command).
#include <string>
#include <vector>

#include "commands.h"
#include "editor/window/editor_app.h"
#include "nimbus/base/error.h"
#include "session.h"

namespace nimbus::sandbox {
namespace {

struct EditOptions {
    std::string scene, script, viewportSize, quality = "fast", mode;
    std::vector<std::string> settings;
    double budgetMs = 0.0;
};

int run(const EditOptions& o) {
    editor::EditorOptions options;
    options.scene = o.scene;
    if (!o.viewportSize.empty()) {
        glm::ivec2 size;
        parseSize(o.viewportSize, size.x, size.y, "--viewport-size");
        options.viewportSize = size;
    }
    options.view = {o.quality, o.mode, o.settings};
    if (o.budgetMs < 0.0) throwInputError("--budget-ms", std::to_string(o.budgetMs), "", "must be > 0");
    options.budgetMs = o.budgetMs;
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
    cmd->add_option("--quality", options->quality, "fast (default), balanced or exact");
    cmd->add_option("--mode", options->mode, "media mode: particles, blocks or billboards");
    cmd->add_option("--set", options->settings, "KEY=VALUE render setting (sandbox settings lists them)");
    cmd->add_option("--budget-ms", options->budgetMs, "walk the quality ladder until frames fit B ms");
    return [options] { return run(*options); };
}

}  // namespace nimbus::sandbox
