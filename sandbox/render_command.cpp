#include "commands.h"

namespace nimbus::sandbox {

CommandRunner addRenderCommand(CLI::App& app) {
    auto* cmd = app.add_subcommand("render", "not implemented yet");
    (void)cmd;
    return [] { return 1; };
}

}  // namespace nimbus::sandbox
