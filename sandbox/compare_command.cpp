#include "commands.h"

namespace nimbus::sandbox {

CommandRunner addCompareCommand(CLI::App& app) {
    auto* cmd = app.add_subcommand("compare", "not implemented yet");
    (void)cmd;
    return [] { return 1; };
}

}  // namespace nimbus::sandbox
