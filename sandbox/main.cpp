// sandbox: Nimbus's command-line front end (docs/design.md §5). Each subcommand lives in its own file.
#include <cstdio>
#include <exception>
#include <map>
#include <string>

#include "commands.h"
#include "nimbus/base/error.h"
#include "nimbus/base/log.h"

int main(int argc, char** argv) {
    using namespace nimbus::sandbox;
    CLI::App app{"Nimbus sandbox: render, judge and measure participating media in glTF scenes"};
    app.require_subcommand(1);
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
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
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
