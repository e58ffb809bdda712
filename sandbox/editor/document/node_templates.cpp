// What `addNode` adds: a node per kind with sensible starting values. Geometry (the box's mesh, the
// cloud's particles) goes into a new buffer held as a data URI, so the document stays one JSON
// until it is saved.
#include <cmath>
#include <cstring>
#include <map>

#include "nimbus/assets/gltf_file.h"
#include "nimbus/assets/scene.h"
#include "nimbus/base/error.h"
#include "scene_edits.h"

namespace nimbus::sandbox::editor {
namespace {

constexpr int kFloat = 5126;
constexpr int kUnsignedShort = 5123;

// A buffer under construction: bytes plus the views and accessors that point into it.
struct BufferBuilder {
    std::vector<unsigned char> bytes;

    // Appends `data` as a new bufferView + accessor and returns the accessor's index.
    template <typename T>
    int add(Json& root, const std::vector<T>& data, int componentType, const char* type, std::size_t count, int target) {
        while (bytes.size() % 4) bytes.push_back(0);
        const std::size_t offset = bytes.size();
        bytes.resize(offset + data.size() * sizeof(T));
        std::memcpy(bytes.data() + offset, data.data(), data.size() * sizeof(T));
        Json view = {{"buffer", bufferIndex(root)}, {"byteOffset", offset}, {"byteLength", data.size() * sizeof(T)}};
        if (target) view["target"] = target;
        root["bufferViews"].push_back(view);
        root["accessors"].push_back({{"bufferView", root["bufferViews"].size() - 1}, {"componentType", componentType},
                                     {"count", count}, {"type", type}});
        return static_cast<int>(root["accessors"].size() - 1);
    }
    static std::size_t bufferIndex(const Json& root) { return root.contains("buffers") ? root["buffers"].size() : 0; }
    void finish(Json& root) {
        root["buffers"].push_back({{"byteLength", bytes.size()}, {"uri", assets::makeDataUri(bytes, "application/octet-stream")}});
    }
};

void useExtension(Json& root, const char* name) {
    Json& used = root["extensionsUsed"];
    for (const Json& e : used)
        if (e == name) return;
    used.push_back(name);
}

Json& mediaExtension(Json& node) { return node["extensions"][assets::kMediaExtension]; }

// The suggested medium of each preset (docs/scene-format.md §3.4); unknown presets get smoke's, and
// the loader then refuses the preset by name.
void addEmitter(Json& node, const std::string& preset) {
    static const std::map<std::string, std::pair<double, double>> media = {
        {"smoke", {4.0, 0.3}}, {"steam", {3.0, 0.6}}, {"vapor_trail", {2.0, 0.6}}, {"fire", {6.0, 0.0}}, {"explosion", {5.0, 0.2}}};
    const std::string name = preset.empty() ? "smoke" : preset;
    const auto it = media.find(name);
    const auto [extinction, g] = it != media.end() ? it->second : media.at("smoke");
    mediaExtension(node) = {{"medium", {{"extinction", extinction}, {"g", g}}}, {"emitter", {{"preset", name}}}};
}

// 40 particles on a Fibonacci spiral inside a 1 m ball: a small puffy cloud.
void addCloud(Json& root, Json& node) {
    constexpr int kCount = 40;
    std::vector<float> positions, radii;
    for (int i = 0; i < kCount; ++i) {
        const double t = (i + 0.5) / kCount;
        const double y = 1.0 - 2.0 * t, ring = std::sqrt(1.0 - y * y), phi = 2.399963229728653 * i;
        const double r = 0.35 + 0.45 * std::fmod(0.618034 * i, 1.0);
        positions.insert(positions.end(), {static_cast<float>(r * ring * std::cos(phi)), static_cast<float>(0.6 * r * y),
                                           static_cast<float>(r * ring * std::sin(phi))});
        radii.push_back(static_cast<float>(0.55 - 0.25 * r));
    }
    BufferBuilder buffer;
    const int position = buffer.add(root, positions, kFloat, "VEC3", kCount, 0);
    const int radius = buffer.add(root, radii, kFloat, "SCALAR", kCount, 0);
    buffer.finish(root);
    mediaExtension(node) = {{"medium", {{"extinction", 3.0}, {"g", 0.4}}},
                            {"particles", {{"position", position}, {"radius", radius}}}};
}

void addLight(Json& root, Json& node) {
    Json& lights = root["extensions"]["KHR_lights_punctual"]["lights"];
    lights.push_back({{"type", "point"}, {"color", {1.0, 1.0, 1.0}}, {"intensity", 20.0}, {"name", node["name"]}});
    node["extensions"]["KHR_lights_punctual"] = {{"light", lights.size() - 1}};
    useExtension(root, "KHR_lights_punctual");
}

// A 1 m cube with flat normals: 24 vertices, 36 indices.
void addBox(Json& root, Json& node) {
    std::vector<float> positions, normals;
    std::vector<std::uint16_t> indices;
    for (int axis = 0; axis < 3; ++axis)
        for (int side = -1; side <= 1; side += 2) {
            const auto base = static_cast<std::uint16_t>(positions.size() / 3);
            for (int corner = 0; corner < 4; ++corner) {
                float p[3];
                const int u = (axis + 1) % 3, v = (axis + 2) % 3;
                p[axis] = 0.5f * static_cast<float>(side);
                p[u] = (corner == 1 || corner == 2) ? 0.5f : -0.5f;
                p[v] = (corner >= 2) ? 0.5f : -0.5f;
                positions.insert(positions.end(), p, p + 3);
                float n[3] = {0.0f, 0.0f, 0.0f};
                n[axis] = static_cast<float>(side);
                normals.insert(normals.end(), n, n + 3);
            }
            // Counter-clockwise seen from outside: the winding flips with the side.
            const std::uint16_t a = base, b = static_cast<std::uint16_t>(base + 1), c = static_cast<std::uint16_t>(base + 2),
                                d = static_cast<std::uint16_t>(base + 3);
            if (side > 0) indices.insert(indices.end(), {a, b, c, a, c, d});
            else indices.insert(indices.end(), {a, c, b, a, d, c});
        }
    BufferBuilder buffer;
    const int position = buffer.add(root, positions, kFloat, "VEC3", 24, 34962);
    root["accessors"][static_cast<std::size_t>(position)]["min"] = {-0.5, -0.5, -0.5};
    root["accessors"][static_cast<std::size_t>(position)]["max"] = {0.5, 0.5, 0.5};
    const int normal = buffer.add(root, normals, kFloat, "VEC3", 24, 34962);
    const int index = buffer.add(root, indices, kUnsignedShort, "SCALAR", 36, 34963);
    buffer.finish(root);
    // A matte grey: glTF's default metallicFactor is 1, so a non-metal says 0.
    root["materials"].push_back({{"name", node["name"]},
                                 {"pbrMetallicRoughness", {{"baseColorFactor", {0.8, 0.8, 0.8, 1.0}}, {"metallicFactor", 0.0}, {"roughnessFactor", 1.0}}}});
    Json primitive = {{"attributes", {{"POSITION", position}, {"NORMAL", normal}}},
                      {"indices", index},
                      {"material", root["materials"].size() - 1}};
    Json mesh = {{"name", node["name"]}, {"primitives", Json::array()}};
    mesh["primitives"].push_back(std::move(primitive));
    root["meshes"].push_back(std::move(mesh));
    node["mesh"] = root["meshes"].size() - 1;
}

void addCamera(Json& root, Json& node) {
    root["cameras"].push_back({{"name", node["name"]}, {"type", "perspective"}, {"perspective", {{"yfov", 0.8}, {"znear", 0.05}}}});
    node["camera"] = root["cameras"].size() - 1;
}

}  // namespace

int addNode(Json& root, NodeKind kind, const std::string& name, int parent, const glm::dvec3& position, const std::string& preset) {
    if (name.empty()) throwInputError("", "add", "name", "a new node needs a name");
    if (findNode(root, name) >= 0) throwInputError("", "add", "name", "a node named '" + name + "' already exists");
    if (parent >= nodeCount(root)) throwInputError("", "add", "parent", "no node " + std::to_string(parent));
    Json node = {{"name", name}};
    if (position != glm::dvec3(0.0)) node["translation"] = {position.x, position.y, position.z};
    switch (kind) {
        case NodeKind::Emitter: addEmitter(node, preset); break;
        case NodeKind::Cloud: addCloud(root, node); break;
        case NodeKind::Light: addLight(root, node); break;
        case NodeKind::Box: addBox(root, node); break;
        case NodeKind::Camera: addCamera(root, node); break;
    }
    if (kind == NodeKind::Emitter || kind == NodeKind::Cloud) useExtension(root, assets::kMediaExtension);
    const int index = nodeCount(root);
    root["nodes"].push_back(std::move(node));
    if (parent >= 0) {
        root["nodes"][static_cast<std::size_t>(parent)]["children"].push_back(index);
    } else if (root.contains("scenes") && !root["scenes"].empty()) {
        root["scenes"][root.value("scene", 0)]["nodes"].push_back(index);
    }
    return index;
}

}  // namespace nimbus::sandbox::editor
