#include "commands.h"

namespace nimbus::sandbox {

CommandRunner addValidateCommand(CLI::App& app) {
    auto* cmd = app.add_subcommand("validate", "not implemented yet");
    (void)cmd;
    return [] { return 1; };
}

}  // namespace nimbus::sandbox
