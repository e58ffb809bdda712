#pragma once
// The editor's edits of a glTF document, made on its JSON: what the outliner, the inspector and the
// script commands change. Each edit either completes or throws InputError naming what was wrong,
// leaving the JSON as it was. Whether the result is a valid scene is the loader's call (EditSession
// loads every edit before accepting it).
//
// Does not: validate field values (the loader does), or touch buffers other than the data URIs of
// what `addNode` creates.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

namespace nimbus::sandbox::editor {

using Json = nlohmann::json;

// The node named `name`, or -1.
int findNode(const Json& root, const std::string& name);
// The node's name, or "node N" for an unnamed one.
std::string nodeLabel(const Json& root, int node);
int nodeCount(const Json& root);
int parentOf(const Json& root, int node);           // -1 for a root node
std::vector<int> childrenOf(const Json& root, int node);
std::vector<int> sceneRoots(const Json& root);       // the shown scene's root nodes, in order

// A dotted path into node `node` (-1: the root object), e.g. "extensions.NIMBUS_participating_media.medium.g"
// or "translation.1". Objects on the way are created; a null value removes the field.
void setField(Json& root, int node, const std::string& path, const Json& value);
// The value at the path, or null when absent.
Json getField(const Json& root, int node, const std::string& path);

enum class NodeKind { Emitter, Cloud, Light, Box, Camera };
std::optional<NodeKind> parseNodeKind(std::string_view text);  // emitter|cloud|light|box|camera

// Adds a node of `kind` named `name` (unique) under `parent` (-1: the scene's roots) at `position`
// in its parent's frame. An emitter takes `preset` (default smoke) with the medium it was tuned
// with. Returns the node's index.
int addNode(Json& root, NodeKind kind, const std::string& name, int parent = -1, const glm::dvec3& position = glm::dvec3(0.0),
            const std::string& preset = "");
// Removes the node and its descendants; every node index in the document is renumbered and
// animation channels that targeted them go. Refused for a node a skin uses.
void deleteNode(Json& root, int node);
// Copies the node and its descendants beside it; names get " copy" (then " copy 2", ...). Returns the copy.
int duplicateNode(Json& root, int node);
void renameNode(Json& root, int node, const std::string& name);
// Moves the node under `parent` (-1: a scene root), keeping its local transform. Refuses cycles.
void reparentNode(Json& root, int node, int parent);

}  // namespace nimbus::sandbox::editor
