#include "editor_state.h"

#include <cmath>

#include "nimbus/base/error.h"
#include "nimbus/base/log.h"
#include "nimbus/base/settings.h"
#include "nimbus/scene/scene_plugin.h"

namespace nimbus::sandbox::editor {

EditorState::EditorState(ViewSettings view, std::size_t historyLimitBytes)
    : view_(std::move(view)), document_(Document::empty()), history_(historyLimitBytes) {
    session_ = buildSession(document_, 0.0, view_);
}

std::unique_ptr<Session> EditorState::buildSession(const Document& document, double time, const ViewSettings& view) const {
    SessionOptions options;
    options.time = time;
    options.settings = view.settings;
    if (!view.mode.empty()) options.options.emplace_back("mode=" + view.mode, "the editor's mode");
    if (!view.quality.empty()) options.options.emplace_back("quality=" + view.quality, "the editor's quality");
    options.defaultQuality = kRenderDefaultQuality;
    return std::make_unique<Session>(std::make_shared<const assets::Scene>(document.load()), options);
}

void EditorState::replaceSession(std::unique_ptr<Session> next) {
    if (session_) next->adoptRenderers(*session_);
    session_ = std::move(next);
    ++revision_;
}

// ---- files ------------------------------------------------------------------------------------

void EditorState::open(const std::filesystem::path& file) {
    Document next = Document::open(file);
    auto session = buildSession(next, 0.0, view_);
    document_ = std::move(next);
    history_.clear();
    selected_ = -1;
    time_ = 0.0;
    replaceSession(std::move(session));
}

void EditorState::newDocument() {
    Document next = Document::empty();
    replaceSession(buildSession(next, 0.0, view_));
    document_ = std::move(next);
    history_.clear();
    selected_ = -1;
    time_ = 0.0;
}

void EditorState::save() {
    if (document_.isUntitled()) throwInputError("save", "", "", "the scene has no file yet: use save FILE (Save As)");
    saveAs(document_.path());
}

void EditorState::saveAs(const std::filesystem::path& file) {
    document_.saveAs(file);
    history_.markSaved();
}

// ---- selection --------------------------------------------------------------------------------

void EditorState::select(int node) {
    if (node < -1 || node >= nodeCount(json())) throwInputError("select", "node " + std::to_string(node), "", "no such node");
    selected_ = node;
}

void EditorState::selectByName(const std::string& name) {
    const int node = findNode(json(), name);
    if (node < 0) throwInputError(document_.path().string(), "select", "", "no node is named '" + name + "'");
    selected_ = node;
}

int EditorState::requireSelection(const char* what) const {
    if (selected_ < 0) throwInputError("", what, "", "no node is selected (select NODE_NAME first)");
    return selected_;
}

// ---- edits ------------------------------------------------------------------------------------

// The edited JSON must load and spawn before it replaces anything: the loader's message is the
// refusal, and the document, history and session stay as they were.
void EditorState::apply(const std::string& label, const Change& change, int selectionAfter) {
    Document next = document_;
    change(next.json());
    auto session = buildSession(next, time_, view_);
    const std::size_t dropped = history_.push({label, document_.json(), next.json(), selected_, selectionAfter});
    document_ = std::move(next);
    selected_ = selectionAfter;
    replaceSession(std::move(session));
    if (dropped > 0) reportDropped(dropped);
}

// The first drop after a file is opened goes to the log; every drop to the notice the window shows.
void EditorState::reportDropped(std::size_t dropped) {
    const std::size_t bytes = history_.limitBytes();
    const std::string limit = bytes >= (std::size_t{1} << 20) ? std::to_string(bytes >> 20) + " MiB" : std::to_string(bytes >> 10) + " KiB";
    notice_ = "undo history at its " + limit + " limit: dropped the oldest " + std::to_string(dropped) +
              (dropped == 1 ? " step" : " steps") + " (" + std::to_string(history_.droppedSinceClear()) + " so far, " +
              std::to_string(history_.size()) + " kept)";
    if (history_.droppedSinceClear() == dropped)
        log::warn("the undo history reached its " + limit + " limit: the oldest steps are dropped from now on");
}

std::optional<std::string> EditorState::takeNotice() {
    auto out = std::move(notice_);
    notice_.reset();
    return out;
}

void EditorState::set(const std::vector<FieldEdit>& edits, const std::string& label) {
    apply(label, [&](Json& root) {
        for (const FieldEdit& e : edits) setField(root, e.node, e.path, e.value);
    }, selected_);
}

void EditorState::setOnSelected(const std::string& path, const Json& value) {
    set({{requireSelection("set"), path, value}}, "set " + path);
}

int EditorState::add(NodeKind kind, const std::string& name, const glm::dvec3& position, const std::string& preset) {
    const int added = nodeCount(json());  // new nodes are appended
    apply("add " + name, [&](Json& root) { addNode(root, kind, name, -1, position, preset); }, added);
    return added;
}

void EditorState::removeSelected() {
    const int node = requireSelection("delete");
    apply("delete " + nodeLabel(json(), node), [&](Json& root) { deleteNode(root, node); }, -1);
}

int EditorState::duplicateSelected() {
    const int node = requireSelection("duplicate");
    const int copy = nodeCount(json());
    apply("duplicate " + nodeLabel(json(), node), [&](Json& root) { duplicateNode(root, node); }, copy);
    return copy;
}

void EditorState::renameSelected(const std::string& name) {
    const int node = requireSelection("rename");
    apply("rename " + nodeLabel(json(), node), [&](Json& root) { renameNode(root, node, name); }, node);
}

void EditorState::reparentSelected(int parent) {
    const int node = requireSelection("reparent");
    apply("reparent " + nodeLabel(json(), node), [&](Json& root) { reparentNode(root, node, parent); }, node);
}

// The step's state is loaded before the history moves, so a step that no longer loads (the view
// settings changed since) leaves everything where it was.
bool EditorState::undo() {
    auto target = history_.peekUndo();
    if (!target) return false;
    Document previous = document_;
    previous.json() = std::move(target->json);
    auto session = buildSession(previous, time_, view_);
    history_.undo();
    selected_ = target->selection;
    document_ = std::move(previous);
    replaceSession(std::move(session));
    return true;
}

bool EditorState::redo() {
    auto target = history_.peekRedo();
    if (!target) return false;
    Document next = document_;
    next.json() = std::move(target->json);
    auto session = buildSession(next, time_, view_);
    history_.redo();
    selected_ = target->selection;
    document_ = std::move(next);
    replaceSession(std::move(session));
    return true;
}

// ---- time and view settings -------------------------------------------------------------------

void EditorState::scrub(double seconds) {
    (void)scene::simulationSteps(seconds, session_->app().timeStep());  // refused before the session is rebuilt
    replaceSession(buildSession(document_, seconds, view_));
    time_ = seconds;
}

void EditorState::advance(double seconds) {
    if (!std::isfinite(seconds) || seconds < 0.0)
        throwInputError("play", formatSettingNumber(seconds), "", "must be a finite number of seconds >= 0");
    scene::simulateTo(session_->app(), time_ + seconds);  // refuses a time beyond the step limit, unchanged
    time_ += seconds;
    ++revision_;
}

void EditorState::setQuality(const std::string& quality) {
    ViewSettings next = view_;
    next.quality = quality;
    std::erase_if(next.settings, [](const std::string& s) { return s.rfind("quality=", 0) == 0; });  // the latest choice wins
    setView(next);
}

void EditorState::setMode(const std::string& mode) {
    ViewSettings next = view_;
    next.mode = mode;
    std::erase_if(next.settings, [](const std::string& s) { return s.rfind("mode=", 0) == 0; });
    setView(next);
}

void EditorState::setSetting(const std::string& key, const std::string& value) {
    ViewSettings next = view_;
    std::erase_if(next.settings, [&](const std::string& s) { return s.rfind(key + "=", 0) == 0; });
    if (!value.empty()) next.settings.push_back(key + "=" + value);
    setView(next);
}

void EditorState::setView(const ViewSettings& view) {
    replaceSession(buildSession(document_, time_, view));
    view_ = view;
}

}  // namespace nimbus::sandbox::editor
