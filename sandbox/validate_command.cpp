// sandbox validate SCENE [--time T]
// Loads and checks the whole scene without a GPU, then prints what it contains and what rendering
// it needs (shadow views, light slices per light, particles). Exit 0 when the scene is valid.
#include <cstdio>

#include "cli_options.h"
#include "commands.h"
#include "scene_summary.h"
#include "session.h"

namespace nimbus::sandbox {
namespace {

struct ValidateOptions {
    std::string scene;
    std::string time = "0";
};

int run(const ValidateOptions& o) {
    Session session({o.scene, parseTime(o.time), {}});
    std::fputs(summarizeScene(session, o.scene).c_str(), stdout);
    return 0;
}

}  // namespace

CommandRunner addValidateCommand(CLI::App& app) {
    auto options = std::make_shared<ValidateOptions>();
    auto* cmd = app.add_subcommand("validate", "load and check a scene, and print what rendering it needs");
    cmd->add_option("scene", options->scene, "glTF scene (.gltf or .glb)")->required();
    addTimeOption(cmd, options->time);
    return [options] { return run(*options); };
}

}  // namespace nimbus::sandbox
