#pragma once
// The editor's panels, one per file. Each draws the inside of its ImGui window from the editor's
// state and sends edits through it; refusals come back as the loader's one-line message.
//
// Does not: lay windows out (EditorApp does) or own the state.
#include <filesystem>
#include <optional>
#include <string>

#include "editor_state.h"
#include "panels/field_widgets.h"

namespace nimbus::sandbox::editor {

class ViewportPanel;
class ReferenceSnapshot;
class RecentFiles;

// The menu bar and the file dialogs: new, open, recent files, save, save as, quit, undo and redo,
// and the camera the viewport looks through. Opening or quitting with unsaved changes asks first.
struct FilesMenu {
    std::string pathBuffer;                             // the Open / Save As dialogs' typed path
    std::optional<std::filesystem::path> pendingOpen;   // waits for the unsaved-changes answer
    bool pendingQuit = false;
    bool showOpen = false, showSaveAs = false, askUnsaved = false;
    bool quit = false;                                  // the app closes now
};
std::optional<std::string> drawMenuBar(EditorState& state, FilesMenu& menu, RecentFiles& recent, ViewportPanel& viewport);
// The window's close button: quits, or asks first when there are unsaved changes.
void requestQuit(EditorState& state, FilesMenu& menu);

// The node tree: select, add, delete, duplicate, rename (double-click) and re-parent (drag and drop).
// `renameBuffer` holds the half-typed name while the rename popup is open.
std::optional<std::string> drawOutliner(EditorState& state, const glm::dvec3& addPosition, std::string& renameBuffer);

// Every field of the selected node, or the scene's environment when nothing is selected.
void drawInspector(EditorState& state, FieldWidgets& fields);

struct Playback {
    bool playing = false;
    bool loop = true;
    double end = 10.0;  // s: where playback loops or stops
};
// Play, pause, step, scrub and loop over scene time.
std::optional<std::string> drawTimeline(EditorState& state, Playback& playback);

struct PerformanceRequest {
    bool takeReference = false;
    bool stopReference = false;  // keep the picture so far
    bool applyBudget = false;
};
// Frame time per pass, particle counts, mode and quality, the frame budget, the reference snapshot.
std::optional<std::string> drawPerformance(EditorState& state, const ViewportPanel& viewport, const ReferenceSnapshot& snapshot,
                                           double& budgetMs, PerformanceRequest& request);

}  // namespace nimbus::sandbox::editor
