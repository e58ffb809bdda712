// The menu bar with the file dialogs and the unsaved-changes prompt. A file that fails to open
// leaves the current scene in place and shows the loader's message.
#include <functional>

#include <imgui.h>
#include <imgui_stdlib.h>

#include "services/recent_files.h"
#include "viewport_panel.h"
#include "nimbus/base/error.h"
#include "panels.h"

namespace nimbus::sandbox::editor {
namespace {

std::optional<std::string> openNow(EditorState& state, RecentFiles& recent, const std::filesystem::path& file) {
    try {
        state.open(file);
        recent.add(file);
    } catch (const InputError& e) {
        return e.what();
    }
    return std::nullopt;
}

// Opens `file`, or asks first when there are unsaved changes.
std::optional<std::string> requestOpen(EditorState& state, FilesMenu& menu, RecentFiles& recent, const std::filesystem::path& file) {
    if (!state.dirty()) return openNow(state, recent, file);
    menu.pendingOpen = file;
    menu.askUnsaved = true;
    return std::nullopt;
}

std::optional<std::string> saveNow(EditorState& state, RecentFiles& recent, const std::optional<std::filesystem::path>& as) {
    try {
        if (as) state.saveAs(*as);
        else state.save();
        recent.add(state.document().path());
    } catch (const InputError& e) {
        return e.what();
    }
    return std::nullopt;
}

void cameraMenu(EditorState& state, ViewportPanel& viewport) {
    if (!ImGui::BeginMenu("View")) return;
    if (ImGui::MenuItem("Free camera", nullptr, viewport.freeCamera())) viewport.useFreeCamera(state);
    if (ImGui::MenuItem("Scene's first camera", nullptr, !viewport.freeCamera() && viewport.sceneCamera().empty()))
        viewport.viewThrough("");
    for (int i = 0; i < nodeCount(state.json()); ++i) {
        const Json camera = getField(state.json(), i, "camera");
        const Json name = getField(state.json(), i, "name");
        if (!camera.is_number_integer() || !name.is_string()) continue;
        const std::string label = "Through " + name.get<std::string>();
        if (ImGui::MenuItem(label.c_str(), nullptr, !viewport.freeCamera() && viewport.sceneCamera() == name.get<std::string>()))
            viewport.viewThrough(name.get<std::string>());
    }
    ImGui::EndMenu();
}

void editMenu(EditorState& state, std::optional<std::string>& error) {
    if (!ImGui::BeginMenu("Edit")) return;
    try {
        const std::string undo = "Undo " + state.history().undoLabel(), redo = "Redo " + state.history().redoLabel();
        if (ImGui::MenuItem(undo.c_str(), "Ctrl+Z", false, state.history().canUndo())) state.undo();
        if (ImGui::MenuItem(redo.c_str(), "Ctrl+Y", false, state.history().canRedo())) state.redo();
        if (ImGui::MenuItem("Duplicate", nullptr, false, state.selected() >= 0)) state.duplicateSelected();
        if (ImGui::MenuItem("Delete", "Del", false, state.selected() >= 0)) state.removeSelected();
    } catch (const InputError& e) {
        error = e.what();
    }
    ImGui::EndMenu();
}

void fileMenu(EditorState& state, FilesMenu& menu, RecentFiles& recent, std::optional<std::string>& error) {
    if (!ImGui::BeginMenu("File")) return;
    if (ImGui::MenuItem("New")) {
        if (state.dirty()) menu.pendingOpen = std::filesystem::path(), menu.askUnsaved = true;
        else state.newDocument();
    }
    if (ImGui::MenuItem("Open...", "Ctrl+O")) menu.showOpen = true;
    if (ImGui::BeginMenu("Open Recent", !recent.files().empty())) {
        for (const std::string& file : recent.files())
            if (ImGui::MenuItem(file.c_str())) error = requestOpen(state, menu, recent, file);
        ImGui::EndMenu();
    }
    if (ImGui::MenuItem("Save", "Ctrl+S", false, !state.document().isUntitled())) error = saveNow(state, recent, std::nullopt);
    if (ImGui::MenuItem("Save As...")) menu.showSaveAs = true;
    ImGui::Separator();
    if (ImGui::MenuItem("Quit")) requestQuit(state, menu);
    ImGui::EndMenu();
}

void pathDialog(const char* title, bool& show, std::string& buffer, const std::function<void(const std::string&)>& accept) {
    if (show) ImGui::OpenPopup(title), show = false;
    if (!ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
    ImGui::TextUnformatted("File (.gltf or .glb):");
    ImGui::SetNextItemWidth(520);
    if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
    const bool entered = ImGui::InputText("##path", &buffer, ImGuiInputTextFlags_EnterReturnsTrue);
    if (entered || ImGui::Button("OK")) {
        accept(buffer);
        ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
}

void unsavedPrompt(EditorState& state, FilesMenu& menu, RecentFiles& recent, std::optional<std::string>& error) {
    if (menu.askUnsaved) ImGui::OpenPopup("Unsaved changes"), menu.askUnsaved = false;
    if (!ImGui::BeginPopupModal("Unsaved changes", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
    ImGui::Text("%s has unsaved changes.", state.document().isUntitled() ? "The scene" : state.document().path().string().c_str());
    auto proceed = [&] {
        if (menu.pendingQuit) menu.quit = true;
        else if (menu.pendingOpen && menu.pendingOpen->empty()) state.newDocument();
        else if (menu.pendingOpen) error = openNow(state, recent, *menu.pendingOpen);
        menu.pendingOpen.reset();
        menu.pendingQuit = false;
        ImGui::CloseCurrentPopup();
    };
    if (ImGui::Button("Save") && !state.document().isUntitled()) {
        error = saveNow(state, recent, std::nullopt);
        if (!error) proceed();
    }
    ImGui::SameLine();
    if (ImGui::Button("Discard")) proceed();
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) {
        menu.pendingOpen.reset();
        menu.pendingQuit = false;
        ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
}

}  // namespace

void requestQuit(EditorState& state, FilesMenu& menu) {
    if (!state.dirty()) {
        menu.quit = true;
        return;
    }
    menu.pendingQuit = true;
    menu.askUnsaved = true;
}

std::optional<std::string> drawMenuBar(EditorState& state, FilesMenu& menu, RecentFiles& recent, ViewportPanel& viewport) {
    std::optional<std::string> error;
    if (ImGui::BeginMainMenuBar()) {
        fileMenu(state, menu, recent, error);
        editMenu(state, error);
        cameraMenu(state, viewport);
        ImGui::EndMainMenuBar();
    }
    pathDialog("Open", menu.showOpen, menu.pathBuffer, [&](const std::string& file) { error = requestOpen(state, menu, recent, file); });
    pathDialog("Save As", menu.showSaveAs, menu.pathBuffer, [&](const std::string& file) { error = saveNow(state, recent, file); });
    unsavedPrompt(state, menu, recent, error);
    return error;
}

}  // namespace nimbus::sandbox::editor
