#include "commands.h"

namespace nimbus::sandbox {

CommandRunner addReferenceCommand(CLI::App& app) {
    auto* cmd = app.add_subcommand("reference", "not implemented yet");
    (void)cmd;
    return [] { return 1; };
}

}  // namespace nimbus::sandbox
