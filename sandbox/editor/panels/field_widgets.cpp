#include "field_widgets.h"

#include <algorithm>

#include <imgui.h>
#include <imgui_stdlib.h>

#include "nimbus/base/error.h"

namespace nimbus::sandbox::editor {
namespace {

Json current(const EditorState& state, int node, const std::string& path, const Json& fallback) {
    Json value = getField(state.json(), node, path);
    return value.is_null() ? fallback : value;
}

std::vector<double> numbers(const Json& value, int count) {
    std::vector<double> out(static_cast<std::size_t>(count), 0.0);
    if (value.is_array())
        for (std::size_t i = 0; i < out.size() && i < value.size(); ++i)
            if (value[i].is_number()) out[i] = value[i].get<double>();
    return out;
}

// Built with append: GCC 12 warns falsely (-Wrestrict) on chains of operator+ here.
std::string join(const std::string& path, const std::string& part) {
    if (path.empty()) return part;
    std::string out = path;
    out.append(1, '.').append(part);
    return out;
}

}  // namespace

std::string FieldWidgets::key(int node, const std::string& path) {
    std::string out = std::to_string(node);
    out.append(1, ':').append(path);
    return out;
}

void FieldWidgets::commit(int node, const std::string& path, const Json& value) {
    try {
        if (node >= 0 && node == state_->selected() && path == "name" && value.is_string())
            state_->renameSelected(value.get<std::string>());  // names stay unique: scripts select by name
        else
            state_->set({{node, path, value}}, "set " + path);
        errorKey_.clear();
    } catch (const InputError& e) {
        errorKey_ = key(node, path);
        errorText_ = e.what();
        pending_ = errorText_;
    }
}

void FieldWidgets::showError(int node, const std::string& path) {
    if (errorKey_ != key(node, path)) return;
    ImGui::PushStyleColor(ImGuiCol_Text, IM_COL32(255, 110, 90, 255));
    ImGui::TextWrapped("%s", errorText_.c_str());
    ImGui::PopStyleColor();
}

std::optional<std::string> FieldWidgets::takeError() {
    auto out = std::move(pending_);
    pending_.reset();
    return out;
}

void FieldWidgets::number(const char* label, int node, const std::string& path, double fallback, float speed) {
    const std::string k = key(node, path);
    const bool editing = editing_.count(k) != 0;
    double value = editing ? editing_[k].get<double>() : current(*state_, node, path, fallback).get<double>();
    ImGui::DragScalar(label, ImGuiDataType_Double, &value, speed, nullptr, nullptr, "%.6g");
    if (ImGui::IsItemActive()) editing_[k] = value;
    if (ImGui::IsItemDeactivated()) {
        editing_.erase(k);
        if (ImGui::IsItemDeactivatedAfterEdit()) commit(node, path, value);
    }
    showError(node, path);
}

void FieldWidgets::integer(const char* label, int node, const std::string& path, int fallback) {
    const Json v = current(*state_, node, path, fallback);
    int value = v.is_number() ? v.get<int>() : fallback;
    ImGui::InputInt(label, &value);
    if (ImGui::IsItemDeactivatedAfterEdit() || (ImGui::IsItemEdited() && !ImGui::IsItemActive())) commit(node, path, value);
    showError(node, path);
}

void FieldWidgets::vector(const char* label, int node, const std::string& path, int components, const Json& fallback, float speed) {
    const std::string k = key(node, path);
    std::vector<double> value = numbers(editing_.count(k) ? editing_[k] : current(*state_, node, path, fallback), components);
    ImGui::DragScalarN(label, ImGuiDataType_Double, value.data(), components, speed, nullptr, nullptr, "%.4g");
    if (ImGui::IsItemActive()) editing_[k] = value;
    if (ImGui::IsItemDeactivated()) {
        editing_.erase(k);
        if (ImGui::IsItemDeactivatedAfterEdit()) commit(node, path, value);
    }
    showError(node, path);
}

void FieldWidgets::colour(const char* label, int node, const std::string& path, const Json& fallback, bool hdr) {
    const std::string k = key(node, path);
    const std::vector<double> value = numbers(editing_.count(k) ? editing_[k] : current(*state_, node, path, fallback), 3);
    float rgb[3] = {static_cast<float>(value[0]), static_cast<float>(value[1]), static_cast<float>(value[2])};
    ImGuiColorEditFlags flags = ImGuiColorEditFlags_Float;
    if (hdr) flags |= ImGuiColorEditFlags_HDR;
    ImGui::ColorEdit3(label, rgb, flags);
    const Json edited = {rgb[0], rgb[1], rgb[2]};
    if (ImGui::IsItemActive()) editing_[k] = edited;
    if (ImGui::IsItemDeactivated()) editing_.erase(k);
    if (ImGui::IsItemDeactivatedAfterEdit()) commit(node, path, edited);
    showError(node, path);
}

void FieldWidgets::choice(const char* label, int node, const std::string& path, const std::vector<std::string>& options,
                          const std::string& fallback, bool allowNone) {
    const Json v = getField(state_->json(), node, path);
    const std::string value = v.is_string() ? v.get<std::string>() : fallback;
    if (ImGui::BeginCombo(label, value.empty() ? "(none)" : value.c_str())) {
        if (allowNone && ImGui::Selectable("(none)", value.empty())) commit(node, path, nullptr);
        for (const std::string& option : options)
            if (ImGui::Selectable(option.c_str(), option == value) && option != value) commit(node, path, option);
        ImGui::EndCombo();
    }
    showError(node, path);
}

void FieldWidgets::text(const char* label, int node, const std::string& path) {
    const std::string k = key(node, path);
    const Json v = getField(state_->json(), node, path);
    std::string value = editing_.count(k) ? editing_[k].get<std::string>() : (v.is_string() ? v.get<std::string>() : "");
    ImGui::InputText(label, &value);
    if (ImGui::IsItemActive()) editing_[k] = value;
    if (ImGui::IsItemDeactivated()) {
        editing_.erase(k);
        if (ImGui::IsItemDeactivatedAfterEdit()) commit(node, path, value);
    }
    showError(node, path);
}

void FieldWidgets::tree(const char* label, int node, const std::string& path) {
    const Json value = getField(state_->json(), node, path);
    if (!value.is_null()) treeValue(label, node, path, value);
}

void FieldWidgets::treeValue(const std::string& label, int node, const std::string& path, const Json& value) {
    ImGui::PushID(path.c_str());
    const bool smallVector = value.is_array() && !value.empty() && value.size() <= 4 &&
                             std::all_of(value.begin(), value.end(), [](const Json& v) { return v.is_number(); });
    if (value.is_object() || (value.is_array() && !smallVector)) {
        if (ImGui::TreeNode(label.c_str())) {
            if (value.is_object())
                for (const auto& [name, child] : value.items()) treeValue(name, node, join(path, name), child);
            else
                for (std::size_t i = 0; i < value.size(); ++i) treeValue(std::to_string(i).insert(0, 1, '[').append(1, ']'), node, join(path, std::to_string(i)), value[i]);
            ImGui::TreePop();
        }
    } else if (smallVector) {
        vector(label.c_str(), node, path, static_cast<int>(value.size()), value);
    } else if (value.is_number_integer()) {
        integer(label.c_str(), node, path, value.get<int>());
    } else if (value.is_number()) {
        number(label.c_str(), node, path, value.get<double>());
    } else if (value.is_string()) {
        text(label.c_str(), node, path);
    } else if (value.is_boolean()) {
        bool b = value.get<bool>();
        if (ImGui::Checkbox(label.c_str(), &b)) commit(node, path, b);
        showError(node, path);
    }
    ImGui::PopID();
}

}  // namespace nimbus::sandbox::editor
