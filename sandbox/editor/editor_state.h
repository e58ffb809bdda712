#pragma once
// What the editor edits and shows, apart from any window: the document, its history, the
// selection, scene time and the view settings, and the Session that simulates and renders the
// current state. Every change goes through here, whether it comes from a panel or a script line,
// and either completes or throws InputError with everything left as it was.
//
// Does not: own GL objects or windows (the Session renders into whatever context is current).
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "document/document.h"
#include "document/history.h"
#include "document/scene_edits.h"
#include "session.h"

namespace nimbus::sandbox::editor {

struct ViewSettings {
    std::string quality;                // "" : sandbox render's default
    std::string mode;                   // "" : the scene's or the plugin's default
    std::vector<std::string> settings;  // KEY=VALUE, as --set
};

struct FieldEdit {
    int node = -1;  // -1: the root object
    std::string path;
    Json value;
};

class EditorState {
public:
    // The undo history keeps at most `historyLimitBytes` of document states (History).
    explicit EditorState(ViewSettings view = {}, std::size_t historyLimitBytes = History::kDefaultLimitBytes);

    // ---- files
    void open(const std::filesystem::path& file);  // the current document stays if this throws
    void newDocument();
    void save();                                   // refused while untitled
    void saveAs(const std::filesystem::path& file);
    bool dirty() const { return !history_.atSaved(); }
    const Document& document() const { return document_; }
    const Json& json() const { return document_.json(); }

    // ---- selection (a node index, -1 for none)
    int selected() const { return selected_; }
    void select(int node);
    void selectByName(const std::string& name);

    // ---- edits: one undo step each
    void set(const std::vector<FieldEdit>& edits, const std::string& label);
    void setOnSelected(const std::string& path, const Json& value);
    int add(NodeKind kind, const std::string& name, const glm::dvec3& position = glm::dvec3(0.0), const std::string& preset = "");
    void removeSelected();
    int duplicateSelected();
    void renameSelected(const std::string& name);
    void reparentSelected(int parent);
    bool undo();
    bool redo();
    const History& history() const { return history_; }
    // What the last edits dropped from the undo history, once: "undo history at its 256 MiB limit: ...".
    std::optional<std::string> takeNotice();

    // ---- time: scrubbing re-simulates from 0, playing steps on; both land on the same state
    double time() const { return time_; }
    void scrub(double seconds);
    void advance(double seconds);

    // ---- view settings
    const ViewSettings& view() const { return view_; }
    void setQuality(const std::string& quality);
    void setMode(const std::string& mode);
    // Any declared setting as --set gives it; an empty value unsets it (back to the tier's).
    void setSetting(const std::string& key, const std::string& value);
    void setView(const ViewSettings& view);  // refused settings leave the view as it was

    Session& session() { return *session_; }
    // Grows with every change of what the viewport shows (edits, time, settings).
    std::uint64_t revision() const { return revision_; }

private:
    using Change = std::function<void(Json&)>;
    void apply(const std::string& label, const Change& change, int selectionAfter);
    void replaceSession(std::unique_ptr<Session> next);
    std::unique_ptr<Session> buildSession(const Document& document, double time, const ViewSettings& view) const;
    int requireSelection(const char* what) const;
    void reportDropped(std::size_t dropped);

    ViewSettings view_;
    Document document_;
    History history_;
    std::unique_ptr<Session> session_;
    int selected_ = -1;
    double time_ = 0.0;
    std::uint64_t revision_ = 0;
    std::optional<std::string> notice_;
};

}  // namespace nimbus::sandbox::editor
