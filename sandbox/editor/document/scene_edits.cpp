#include "scene_edits.h"

#include <algorithm>
#include <charconv>
#include <map>
#include <set>

#include "nimbus/base/error.h"

namespace nimbus::sandbox::editor {
namespace {

[[noreturn]] void refuse(const Json& root, int node, const std::string& field, const std::string& problem) {
    throwInputError("", node >= 0 ? nodeLabel(root, node) : "the scene", field, problem);
}

void checkNode(const Json& root, int node) {
    if (node < 0 || node >= nodeCount(root)) throwInputError("", "node " + std::to_string(node), "", "no such node");
}

std::vector<std::string> splitPath(const std::string& path) {
    std::vector<std::string> parts;
    std::size_t start = 0;
    while (start <= path.size()) {
        const auto dot = path.find('.', start);
        parts.push_back(path.substr(start, dot == std::string::npos ? std::string::npos : dot - start));
        if (dot == std::string::npos) break;
        start = dot + 1;
    }
    return parts;
}

std::optional<std::size_t> arrayIndex(const std::string& part) {
    std::size_t index = 0;
    const auto [end, ec] = std::from_chars(part.data(), part.data() + part.size(), index);
    if (ec != std::errc() || end != part.data() + part.size()) return std::nullopt;
    return index;
}

// The JSON array holding node indices of `parent` (-1: the scene's root list), created when missing.
Json* childList(Json& root, int parent) {
    if (parent >= 0) {
        Json& node = root["nodes"][static_cast<std::size_t>(parent)];
        if (!node.contains("children")) node["children"] = Json::array();
        return &node["children"];
    }
    if (!root.contains("scenes") || !root["scenes"].is_array() || root["scenes"].empty()) return nullptr;
    Json& scene = root["scenes"][root.value("scene", 0)];
    if (!scene.contains("nodes")) scene["nodes"] = Json::array();
    return &scene["nodes"];
}

void removeFromList(Json& list, int node) {
    auto& array = list.get_ref<Json::array_t&>();
    array.erase(std::remove(array.begin(), array.end(), Json(node)), array.end());
}

void collectSubtree(const Json& root, int node, std::set<int>& out) {
    out.insert(node);
    for (const int child : childrenOf(root, node)) collectSubtree(root, child, out);
}

// Renumbers a list of node indices: removed ones go, the rest shift down.
void remapList(Json& list, const std::map<int, int>& remap) {
    Json out = Json::array();
    for (const Json& v : list)
        if (const auto it = remap.find(v.get<int>()); it != remap.end()) out.push_back(it->second);
    list = std::move(out);
}

// glTF forbids empty `children` and scene `nodes` arrays: an emptied list goes.
void remapMember(Json& object, const char* key, const std::map<int, int>& remap) {
    if (!object.contains(key)) return;
    remapList(object[key], remap);
    if (object[key].empty()) object.erase(key);
}

void checkNotUsedBySkin(const Json& root, const std::set<int>& removed) {
    if (!root.contains("skins")) return;
    for (std::size_t s = 0; s < root["skins"].size(); ++s) {
        const Json& skin = root["skins"][s];
        bool used = skin.contains("skeleton") && removed.count(skin["skeleton"].get<int>()) != 0;
        for (const Json& j : skin.value("joints", Json::array())) used = used || removed.count(j.get<int>()) != 0;
        if (used) refuse(root, *removed.begin(), "", "skin " + std::to_string(s) + " uses it as a joint; it cannot be deleted");
    }
}

void remapAnimations(Json& root, const std::map<int, int>& remap) {
    if (!root.contains("animations")) return;
    Json kept = Json::array();
    for (Json animation : root["animations"]) {
        Json channels = Json::array();
        for (Json channel : animation["channels"]) {
            Json& target = channel["target"];
            if (target.contains("node")) {
                const auto it = remap.find(target["node"].get<int>());
                if (it == remap.end()) continue;
                target["node"] = it->second;
            }
            channels.push_back(std::move(channel));
        }
        if (channels.empty()) continue;  // glTF requires at least one channel
        animation["channels"] = std::move(channels);
        kept.push_back(std::move(animation));
    }
    if (kept.empty()) root.erase("animations");
    else root["animations"] = std::move(kept);
}

std::string uniqueName(const Json& root, const std::string& base) {
    std::string name = base + " copy";
    for (int n = 2; findNode(root, name) >= 0; ++n) name = base + " copy " + std::to_string(n);
    return name;
}

int copySubtree(Json& root, int node) {
    Json copy = root["nodes"][static_cast<std::size_t>(node)];
    const std::vector<int> children = childrenOf(root, node);
    if (copy.contains("name")) copy["name"] = uniqueName(root, copy["name"].get<std::string>());
    copy.erase("children");
    const int index = nodeCount(root);
    root["nodes"].push_back(std::move(copy));
    for (const int child : children) childList(root, index)->push_back(copySubtree(root, child));
    return index;
}

}  // namespace

int nodeCount(const Json& root) {
    return root.contains("nodes") && root["nodes"].is_array() ? static_cast<int>(root["nodes"].size()) : 0;
}

int findNode(const Json& root, const std::string& name) {
    for (int i = 0; i < nodeCount(root); ++i) {
        const Json& node = root["nodes"][static_cast<std::size_t>(i)];
        if (node.contains("name") && node["name"].is_string() && node["name"].get<std::string>() == name) return i;
    }
    return -1;
}

std::string nodeLabel(const Json& root, int node) {
    if (node < 0 || node >= nodeCount(root)) return "node " + std::to_string(node);
    const Json& n = root["nodes"][static_cast<std::size_t>(node)];
    if (n.contains("name") && n["name"].is_string()) return "node '" + n["name"].get<std::string>() + "'";
    return "node " + std::to_string(node);
}

int parentOf(const Json& root, int node) {
    for (int i = 0; i < nodeCount(root); ++i)
        for (const int child : childrenOf(root, i))
            if (child == node) return i;
    return -1;
}

std::vector<int> childrenOf(const Json& root, int node) {
    const Json& n = root["nodes"][static_cast<std::size_t>(node)];
    return n.contains("children") ? n["children"].get<std::vector<int>>() : std::vector<int>{};
}

std::vector<int> sceneRoots(const Json& root) {
    if (root.contains("scenes") && root["scenes"].is_array() && !root["scenes"].empty()) {
        const Json& scene = root["scenes"][root.value("scene", 0)];
        return scene.contains("nodes") ? scene["nodes"].get<std::vector<int>>() : std::vector<int>{};
    }
    std::vector<int> roots;
    for (int i = 0; i < nodeCount(root); ++i)
        if (parentOf(root, i) < 0) roots.push_back(i);
    return roots;
}

void setField(Json& root, int node, const std::string& path, const Json& value) {
    if (node >= 0) checkNode(root, node);
    const std::vector<std::string> parts = splitPath(path);
    Json* at = node >= 0 ? &root["nodes"][static_cast<std::size_t>(node)] : &root;
    for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
        if (parts[i].empty()) refuse(root, node, path, "the path has an empty part");
        if (at->is_array()) {
            const auto index = arrayIndex(parts[i]);
            if (!index || *index >= at->size()) refuse(root, node, path, "'" + parts[i] + "' is not an index of the array");
            at = &(*at)[*index];
        } else {
            if (!at->is_object() && !at->is_null()) refuse(root, node, path, "'" + parts[i] + "' is inside a value that is not an object");
            at = &(*at)[parts[i]];
        }
    }
    const std::string& last = parts.back();
    if (last.empty()) refuse(root, node, path, "the path has an empty part");
    if (at->is_array()) {
        const auto index = arrayIndex(last);
        if (!index || *index >= at->size()) refuse(root, node, path, "'" + last + "' is not an index of the array");
        (*at)[*index] = value;
    } else if (at->is_object() || at->is_null()) {
        if (value.is_null()) at->erase(last);
        else (*at)[last] = value;
    } else {
        refuse(root, node, path, "'" + last + "' is inside a value that is not an object");
    }
}

Json getField(const Json& root, int node, const std::string& path) {
    if (node >= nodeCount(root)) return nullptr;
    const Json* at = node >= 0 ? &root["nodes"][static_cast<std::size_t>(node)] : &root;
    if (path.empty()) return *at;
    for (const std::string& part : splitPath(path)) {
        if (at->is_array()) {
            const auto index = arrayIndex(part);
            if (!index || *index >= at->size()) return nullptr;
            at = &(*at)[*index];
        } else if (at->is_object() && at->contains(part)) {
            at = &(*at)[part];
        } else {
            return nullptr;
        }
    }
    return *at;
}

std::optional<NodeKind> parseNodeKind(std::string_view text) {
    if (text == "emitter") return NodeKind::Emitter;
    if (text == "cloud") return NodeKind::Cloud;
    if (text == "light") return NodeKind::Light;
    if (text == "box") return NodeKind::Box;
    if (text == "camera") return NodeKind::Camera;
    return std::nullopt;
}

void deleteNode(Json& root, int node) {
    checkNode(root, node);
    std::set<int> removed;
    collectSubtree(root, node, removed);
    checkNotUsedBySkin(root, removed);
    std::map<int, int> remap;
    Json kept = Json::array();
    for (int i = 0; i < nodeCount(root); ++i) {
        if (removed.count(i)) continue;
        remap[i] = static_cast<int>(kept.size());
        kept.push_back(root["nodes"][static_cast<std::size_t>(i)]);
    }
    for (Json& n : kept) remapMember(n, "children", remap);
    root["nodes"] = std::move(kept);
    if (root.contains("scenes"))
        for (Json& scene : root["scenes"]) remapMember(scene, "nodes", remap);
    remapAnimations(root, remap);
}

int duplicateNode(Json& root, int node) {
    checkNode(root, node);
    const int parent = parentOf(root, node);
    const int copy = copySubtree(root, node);
    if (Json* list = childList(root, parent)) list->push_back(copy);
    return copy;
}

void renameNode(Json& root, int node, const std::string& name) {
    checkNode(root, node);
    if (name.empty()) refuse(root, node, "name", "a name cannot be empty");
    const int other = findNode(root, name);
    if (other >= 0 && other != node) refuse(root, node, "name", "another node is already named '" + name + "'");
    root["nodes"][static_cast<std::size_t>(node)]["name"] = name;
}

void reparentNode(Json& root, int node, int parent) {
    checkNode(root, node);
    if (parent >= 0) {
        checkNode(root, parent);
        for (int p = parent; p >= 0; p = parentOf(root, p))
            if (p == node) refuse(root, node, "children", "it cannot become a child of itself or of its descendants");
    }
    const int old = parentOf(root, node);
    if (Json* list = childList(root, old)) removeFromList(*list, node);
    if (old >= 0 && root["nodes"][static_cast<std::size_t>(old)]["children"].empty())
        root["nodes"][static_cast<std::size_t>(old)].erase("children");  // glTF: a present list is not empty
    if (Json* list = childList(root, parent)) list->push_back(node);
}

}  // namespace nimbus::sandbox::editor
