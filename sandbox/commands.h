#pragma once
// Each `sandbox` subcommand registers itself on the CLI11 app and returns the function that runs it.
// Does not: parse global state; every command reads only its own options.
#include <functional>

#include <CLI/CLI.hpp>

namespace nimbus::sandbox {

using CommandRunner = std::function<int()>;  // returns the process exit code

CommandRunner addRenderCommand(CLI::App& app);
CommandRunner addReferenceCommand(CLI::App& app);
CommandRunner addCompareCommand(CLI::App& app);
CommandRunner addValidateCommand(CLI::App& app);
CommandRunner addBenchCommand(CLI::App& app);
CommandRunner addSettingsCommand(CLI::App& app);
CommandRunner addEditCommand(CLI::App& app);
CommandRunner addExportCommand(CLI::App& app);

}  // namespace nimbus::sandbox
