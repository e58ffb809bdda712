#include "script.h"

#include <unistd.h>

#include <charconv>
#include <cstdio>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>

#include "nimbus/base/error.h"

namespace nimbus::sandbox::editor {
namespace {

struct Command {
    std::string name;
    std::string rest;  // the rest of the line, trimmed
};

std::string trim(const std::string& text) {
    const auto begin = text.find_first_not_of(" \t\r");
    if (begin == std::string::npos) return "";
    return text.substr(begin, text.find_last_not_of(" \t\r") - begin + 1);
}

Command split(const std::string& line) {
    const std::string text = trim(line);
    const auto space = text.find_first_of(" \t");
    if (space == std::string::npos) return {text, ""};
    return {text.substr(0, space), trim(text.substr(space + 1))};
}

double number(const std::string& text, const char* what) {
    double value = 0.0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || end != text.data() + text.size()) throwInputError("", what, "", "'" + text + "' is not a number");
    return value;
}

std::string requireArgument(const Command& c, const char* usage) {
    if (c.rest.empty()) throwInputError("", c.name, "", std::string("needs an argument: ") + usage);
    return c.rest;
}

void noArgument(const Command& c) {
    if (!c.rest.empty()) throwInputError("", c.name, "", "takes no argument");
}

void setCommand(EditorState& state, const Command& c) {
    const auto space = c.rest.find_first_of(" \t");
    if (space == std::string::npos) throwInputError("", "set", "", "usage: set PATH JSON_VALUE");
    const std::string path = c.rest.substr(0, space), text = trim(c.rest.substr(space + 1));
    Json value;
    try {
        value = Json::parse(text);
    } catch (const Json::exception&) {
        throwInputError("", "set", path, "'" + text + "' is not a JSON value");
    }
    state.setOnSelected(path, value);
}

// Resident memory as the kernel counts it (Linux's /proc), 0 where it cannot be read.
double residentMiB() {
    std::ifstream statm("/proc/self/statm");
    std::size_t pages = 0, resident = 0;
    if (!(statm >> pages >> resident)) return 0.0;
    return static_cast<double>(resident) * static_cast<double>(sysconf(_SC_PAGESIZE)) / (1024.0 * 1024.0);
}

void memoryCommand(const EditorState& state) {
    const History& h = state.history();
    std::printf("memory: resident %.1f MiB, undo history %.1f MiB of %.0f MiB in %zu steps (%zu dropped)\n", residentMiB(),
                static_cast<double>(h.bytes()) / (1024.0 * 1024.0), static_cast<double>(h.limitBytes()) / (1024.0 * 1024.0),
                h.size(), h.droppedSinceClear());
    std::fflush(stdout);
}

void addCommand(EditorState& state, const Command& c) {
    const Command parts = split(requireArgument(c, "add emitter|cloud|light|box|camera NAME"));
    const auto kind = parseNodeKind(parts.name);
    if (!kind) throwInputError("", "add", "kind", "'" + parts.name + "' is not one of emitter, cloud, light, box, camera");
    state.add(*kind, requireArgument(parts, "a node name"));
}

using Handler = std::function<void(ScriptTarget&, const Command&)>;

const std::map<std::string, Handler>& handlers() {
    static const std::map<std::string, Handler> table = {
        {"select", [](ScriptTarget& t, const Command& c) { t.state().selectByName(requireArgument(c, "a node name")); }},
        {"set", [](ScriptTarget& t, const Command& c) { setCommand(t.state(), c); }},
        {"add", [](ScriptTarget& t, const Command& c) { addCommand(t.state(), c); }},
        {"delete", [](ScriptTarget& t, const Command& c) { noArgument(c); t.state().removeSelected(); }},
        {"duplicate", [](ScriptTarget& t, const Command& c) { noArgument(c); t.state().duplicateSelected(); }},
        {"rename", [](ScriptTarget& t, const Command& c) { t.state().renameSelected(requireArgument(c, "a name")); }},
        {"parent", [](ScriptTarget& t, const Command& c) {
             const std::string name = requireArgument(c, "a node name, or - for the scene root");
             int parent = -1;
             if (name != "-" && (parent = findNode(t.state().json(), name)) < 0)
                 throwInputError("", "parent", "", "no node is named '" + name + "'");
             t.state().reparentSelected(parent);
         }},
        {"undo", [](ScriptTarget& t, const Command& c) {
             noArgument(c);
             if (!t.state().undo()) throwInputError("", "undo", "", "nothing to undo");
         }},
        {"redo", [](ScriptTarget& t, const Command& c) {
             noArgument(c);
             if (!t.state().redo()) throwInputError("", "redo", "", "nothing to redo");
         }},
        {"time", [](ScriptTarget& t, const Command& c) { t.state().scrub(number(requireArgument(c, "seconds"), "time")); }},
        {"play", [](ScriptTarget& t, const Command& c) { t.play(number(requireArgument(c, "seconds"), "play")); }},
        {"quality", [](ScriptTarget& t, const Command& c) { t.state().setQuality(requireArgument(c, "fast|balanced|exact")); }},
        {"mode", [](ScriptTarget& t, const Command& c) { t.state().setMode(requireArgument(c, "a media mode")); }},
        {"camera", [](ScriptTarget& t, const Command& c) { t.viewThrough(requireArgument(c, "a camera name, or - for the free camera")); }},
        {"frames", [](ScriptTarget& t, const Command& c) {
             const double n = number(requireArgument(c, "a frame count"), "frames");
             if (n < 1 || n > 100000 || n != static_cast<int>(n)) throwInputError("", "frames", "", "must be a whole number in 1..100000");
             t.renderFrames(static_cast<int>(n));
         }},
        {"screenshot", [](ScriptTarget& t, const Command& c) { t.screenshot(requireArgument(c, "FILE.png")); }},
        {"viewport", [](ScriptTarget& t, const Command& c) { t.writeViewport(requireArgument(c, "FILE.exr")); }},
        {"reference", [](ScriptTarget& t, const Command& c) { t.reference(c.rest); }},
        {"open", [](ScriptTarget& t, const Command& c) { t.state().open(requireArgument(c, "FILE")); }},
        {"save", [](ScriptTarget& t, const Command& c) {
             if (c.rest.empty()) t.state().save();
             else t.state().saveAs(c.rest);
         }},
        {"memory", [](ScriptTarget& t, const Command& c) { noArgument(c); memoryCommand(t.state()); }},
        {"quit", [](ScriptTarget& t, const Command& c) { noArgument(c); t.quit(); }},
    };
    return table;
}

}  // namespace

std::vector<ScriptLine> readScript(const std::filesystem::path& file) {
    std::ifstream in(file);
    if (!in) throwInputError(file.string(), "", "", "cannot read the script");
    std::ostringstream text;
    text << in.rdbuf();
    return parseScript(text.str());
}

std::vector<ScriptLine> parseScript(const std::string& script) {
    std::istringstream in(script);
    std::vector<ScriptLine> lines;
    std::string text;
    for (int number = 1; std::getline(in, text); ++number) {
        const std::string line = trim(text);
        if (!line.empty() && line[0] != '#') lines.push_back({number, line});
    }
    return lines;
}

void runScriptLine(ScriptTarget& target, const std::filesystem::path& script, const ScriptLine& line) {
    const std::string where = script.string() + ":" + std::to_string(line.number);
    // Names and paths go into the glTF JSON, which is UTF-8 text.
    try {
        (void)Json(line.text).dump();
    } catch (const Json::type_error&) {
        throwInputError(where, "", "", "the line is not UTF-8 text");
    }
    const Command command = split(line.text);
    const auto it = handlers().find(command.name);
    if (it == handlers().end()) throwInputError(where, command.name, "", "unknown command");
    try {
        it->second(target, command);
    } catch (const InputError& e) {
        throw InputError(where + ": " + e.what());
    }
}

}  // namespace nimbus::sandbox::editor
