// sandbox: Nimbus's command-line front end (docs/design.md §5). Each subcommand lives in its own file.
#include <cstdio>
#include <exception>
#include <map>
#include <string>

#include "commands.h"
#include "nimbus/base/error.h"
#include "nimbus/base/log.h"

namespace {

// A parse error as every other refusal: one line, "sandbox: ...", exit 2 (CLI11 would print two
// lines and exit with its own codes).
int refuseArguments(CLI::App& app, const CLI::ParseError& e, int argc, char** argv) {
    std::string command = "sandbox";
    for (const CLI::App* sub : app.get_subcommands()) command += " " + sub->get_name();
    std::string reason = e.what();
    if (app.get_subcommands().empty() && argc > 1 && argv[1][0] != '-') {  // CLI11 would only say one is required
        std::string known;
        for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
            known += (known.empty() ? "" : ", ") + sub->get_name();
        reason = std::string(argv[1]) + ": unknown command (known: " + known + ")";
    }
    if (e.get_name() == "ArgumentMismatch" && reason.find("flag override") != std::string::npos)
        reason = "--" + reason.substr(0, reason.find(' ')) + ": a flag takes no value";  // CLI11: "NAME was given a disallowed flag override"
    for (char& c : reason)
        if (c == '\n' || c == '\r') c = ' ';
    while (!reason.empty() && reason.back() == ' ') reason.pop_back();
    std::fprintf(stderr, "sandbox: %s (%s --help lists the options)\n", reason.c_str(), command.c_str());
    return 2;
}

}  // namespace

int main(int argc, char** argv) {
    using namespace nimbus::sandbox;
    CLI::App app{"Nimbus sandbox: render, judge and measure participating media in glTF scenes"};
    app.require_subcommand(1);
    // A flag takes no value: "--floor=yes" is refused, not read as on.
    app.option_defaults()->disable_flag_override();
    bool verbose = false;
    app.add_flag("-v,--verbose", verbose, "log progress details");

    std::map<std::string, CommandRunner> runners;
    runners["render"] = addRenderCommand(app);
    runners["reference"] = addReferenceCommand(app);
    runners["compare"] = addCompareCommand(app);
    runners["validate"] = addValidateCommand(app);
    runners["bench"] = addBenchCommand(app);
    runners["settings"] = addSettingsCommand(app);
    runners["edit"] = addEditCommand(app);
    runners["export"] = addExportCommand(app);

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);  // the usage on stdout, exit 0
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        return refuseArguments(app, e, argc, argv);
    }
    nimbus::log::setLevel(verbose ? nimbus::log::Level::Info : nimbus::log::Level::Warn);

    try {
        for (auto* sub : app.get_subcommands()) return runners.at(sub->get_name())();
    } catch (const nimbus::InputError& e) {
        std::fprintf(stderr, "sandbox: %s\n", e.what());
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "sandbox: error: %s\n", e.what());
        return 1;
    }
    return 1;
}
