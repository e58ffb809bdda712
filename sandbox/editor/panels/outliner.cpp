// The outliner: the node tree as the file has it. Click selects; drag a node onto another to
// re-parent it (onto the root row to make it a root); the Add menu and each row's context menu
// hold the rest.
#include <imgui.h>
#include <imgui_stdlib.h>

#include "nimbus/base/error.h"
#include "panels.h"

namespace nimbus::sandbox::editor {
namespace {

constexpr char kDragType[] = "NIMBUS_NODE";

struct OutlinerAction {
    std::optional<std::string> error;
    int reparentNode = -1, reparentTo = -2;  // -2: nothing to do
    bool openRename = false;
};

template <typename F>
void attempt(OutlinerAction& action, F&& f) {
    try {
        f();
    } catch (const InputError& e) {
        action.error = e.what();
    }
}

std::string uniqueName(const Json& root, const std::string& base) {
    std::string name = base;
    for (int n = 2; findNode(root, name) >= 0; ++n) name = base + " " + std::to_string(n);
    return name;
}

void addMenu(EditorState& state, const glm::dvec3& at, OutlinerAction& action) {
    if (!ImGui::BeginPopup("add")) return;
    if (ImGui::BeginMenu("Emitter")) {
        for (const char* preset : {"smoke", "steam", "vapor_trail", "fire", "explosion"})
            if (ImGui::MenuItem(preset))
                attempt(action, [&] { state.add(NodeKind::Emitter, uniqueName(state.json(), preset), at, preset); });
        ImGui::EndMenu();
    }
    const std::pair<const char*, NodeKind> kinds[] = {
        {"Static cloud", NodeKind::Cloud}, {"Light", NodeKind::Light}, {"Box mesh", NodeKind::Box}, {"Camera", NodeKind::Camera}};
    for (const auto& [label, kind] : kinds)
        if (ImGui::MenuItem(label)) attempt(action, [&, kind = kind, label = label] { state.add(kind, uniqueName(state.json(), label), at); });
    ImGui::EndPopup();
}

void contextMenu(EditorState& state, int node, OutlinerAction& action) {
    if (!ImGui::BeginPopupContextItem()) return;
    state.select(node);
    if (ImGui::MenuItem("Rename")) action.openRename = true;
    if (ImGui::MenuItem("Duplicate")) attempt(action, [&] { state.duplicateSelected(); });
    if (ImGui::MenuItem("Delete")) attempt(action, [&] { state.removeSelected(); });
    if (parentOf(state.json(), node) >= 0 && ImGui::MenuItem("Make root")) action.reparentNode = node, action.reparentTo = -1;
    ImGui::EndPopup();
}

void dragAndDrop(int node, OutlinerAction& action) {
    if (ImGui::BeginDragDropSource()) {
        ImGui::SetDragDropPayload(kDragType, &node, sizeof node);
        ImGui::Text("move under...");
        ImGui::EndDragDropSource();
    }
    if (ImGui::BeginDragDropTarget()) {
        if (const ImGuiPayload* payload = ImGui::AcceptDragDropPayload(kDragType)) {
            action.reparentNode = *static_cast<const int*>(payload->Data);
            action.reparentTo = node;
        }
        ImGui::EndDragDropTarget();
    }
}

void nodeRow(EditorState& state, int node, OutlinerAction& action) {
    const std::vector<int> children = childrenOf(state.json(), node);
    ImGuiTreeNodeFlags flags = ImGuiTreeNodeFlags_OpenOnArrow | ImGuiTreeNodeFlags_DefaultOpen | ImGuiTreeNodeFlags_SpanAvailWidth;
    if (children.empty()) flags |= ImGuiTreeNodeFlags_Leaf;
    if (node == state.selected()) flags |= ImGuiTreeNodeFlags_Selected;
    const Json name = getField(state.json(), node, "name");
    const std::string label = name.is_string() ? name.get<std::string>() : "node " + std::to_string(node);
    const bool open = ImGui::TreeNodeEx(reinterpret_cast<void*>(static_cast<std::intptr_t>(node)), flags, "%s", label.c_str());
    if (ImGui::IsItemClicked() && !ImGui::IsItemToggledOpen()) state.select(node);
    if (ImGui::IsItemHovered() && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) action.openRename = true;
    contextMenu(state, node, action);
    dragAndDrop(node, action);
    if (!open) return;
    for (const int child : children) nodeRow(state, child, action);
    ImGui::TreePop();
}

void renamePopup(EditorState& state, OutlinerAction& action, std::string& name) {
    if (action.openRename && state.selected() >= 0) ImGui::OpenPopup("rename");
    if (!ImGui::BeginPopup("rename")) return;
    if (ImGui::IsWindowAppearing()) {
        const Json current = getField(state.json(), state.selected(), "name");
        name = current.is_string() ? current.get<std::string>() : "";
        ImGui::SetKeyboardFocusHere();
    }
    if (ImGui::InputText("name", &name, ImGuiInputTextFlags_EnterReturnsTrue)) {
        attempt(action, [&] { state.renameSelected(name); });
        ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
}

}  // namespace

std::optional<std::string> drawOutliner(EditorState& state, const glm::dvec3& addPosition, std::string& renameBuffer) {
    OutlinerAction action;
    if (ImGui::Button("Add...")) ImGui::OpenPopup("add");
    addMenu(state, addPosition, action);
    ImGui::SameLine();
    ImGui::BeginDisabled(state.selected() < 0);
    if (ImGui::Button("Duplicate")) attempt(action, [&] { state.duplicateSelected(); });
    ImGui::SameLine();
    if (ImGui::Button("Delete")) attempt(action, [&] { state.removeSelected(); });
    ImGui::EndDisabled();
    ImGui::Separator();
    if (ImGui::Selectable("(scene environment)", state.selected() < 0)) state.select(-1);
    if (ImGui::BeginDragDropTarget()) {
        if (const ImGuiPayload* payload = ImGui::AcceptDragDropPayload(kDragType))
            action.reparentNode = *static_cast<const int*>(payload->Data), action.reparentTo = -1;
        ImGui::EndDragDropTarget();
    }
    for (const int node : sceneRoots(state.json())) nodeRow(state, node, action);
    renamePopup(state, action, renameBuffer);
    if (action.reparentTo != -2 && action.reparentNode >= 0) {
        state.select(action.reparentNode);
        attempt(action, [&] { state.reparentSelected(action.reparentTo); });
    }
    return action.error;
}

}  // namespace nimbus::sandbox::editor
