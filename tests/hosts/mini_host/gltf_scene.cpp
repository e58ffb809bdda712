// loadScene: tinygltf reads the file and its buffers; this file turns the JSON-side objects (nodes,
// cameras, lights, materials, the media extension) into mini_host's plain data.
#include "gltf_scene.h"

#include <glm/gtc/type_ptr.hpp>

#include "gltf_data.h"

namespace mini {
namespace {

using Json = nlohmann::json;

// tinygltf's generic JSON value as nlohmann::json (integers stay integers), for the media module.
Json toJson(const tinygltf::Value& v) {
    switch (v.Type()) {
        case tinygltf::BOOL_TYPE: return v.Get<bool>();
        case tinygltf::INT_TYPE: return v.Get<int>();
        case tinygltf::REAL_TYPE: return v.Get<double>();
        case tinygltf::STRING_TYPE: return v.Get<std::string>();
        case tinygltf::ARRAY_TYPE: {
            Json out = Json::array();
            for (std::size_t i = 0; i < v.ArrayLen(); ++i) out.push_back(toJson(v.Get(static_cast<int>(i))));
            return out;
        }
        case tinygltf::OBJECT_TYPE: {
            Json out = Json::object();
            for (const std::string& key : v.Keys()) out[key] = toJson(v.Get(key));
            return out;
        }
        default: return nullptr;  // null, or binary (never in JSON text)
    }
}

Json extension(const tinygltf::ExtensionMap& extensions, const char* name) {
    const auto it = extensions.find(name);
    return it == extensions.end() ? Json() : toJson(it->second);
}

// Images are not drawn: accept every one without decoding it.
bool skipImage(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*) { return true; }

tinygltf::Model readModel(const std::filesystem::path& file) {
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(&skipImage, nullptr);
    tinygltf::Model model;
    std::string err, warn;
    const bool binary = file.extension() == ".glb";
    const bool ok = binary ? loader.LoadBinaryFromFile(&model, &err, &warn, file.string())
                           : loader.LoadASCIIFromFile(&model, &err, &warn, file.string());
    if (!ok) {
        for (char& c : err)
            if (c == '\n') c = ' ';
        while (!err.empty() && err.back() == ' ') err.pop_back();
        throw SceneError(file.string() + ": " + (err.empty() ? std::string("cannot be read") : err));
    }
    return model;
}

glm::vec3 color3(const Json& object, const char* key, glm::vec3 fallback) {
    if (!object.is_object() || !object.contains(key)) return fallback;
    const Json& c = object[key];
    if (!c.is_array() || c.size() != 3) throw SceneError(std::string(key) + ": expected [r, g, b]");
    return glm::vec3(glm::dvec3(c[0].get<double>(), c[1].get<double>(), c[2].get<double>()));
}

// KHR_lights_punctual from the root extension's JSON, with the spec's defaults.
std::vector<Light> readLights(const Json& root, const std::string& file) {
    std::vector<Light> out;
    if (!root.is_object() || !root.contains("lights")) return out;
    for (const Json& l : root["lights"]) {
        Light light;
        light.name = l.value("name", "");
        const std::string type = l.value("type", "");
        if (type != "directional" && type != "point" && type != "spot")
            throw SceneError(file + ": KHR_lights_punctual: light \"" + light.name + "\": unknown type \"" + type + "\"");
        light.kind = type == "point" ? nimbus::gpu::LightKind::Point : type == "spot" ? nimbus::gpu::LightKind::Spot
                                                                                      : nimbus::gpu::LightKind::Directional;
        light.color = color3(l, "color", glm::vec3(1.0f));
        light.intensity = static_cast<float>(l.value("intensity", 1.0));
        light.range = l.value("range", 0.0);
        if (l.contains("spot")) {
            light.innerConeAngle = l["spot"].value("innerConeAngle", 0.0);
            light.outerConeAngle = l["spot"].value("outerConeAngle", 0.7853981633974483);
        }
        out.push_back(light);
    }
    return out;
}

Node readNode(const tinygltf::Node& src) {
    Node n;
    n.name = src.name;
    n.children = src.children;
    n.mesh = src.mesh;
    n.camera = src.camera;
    if (src.matrix.size() == 16) {
        n.hasMatrix = true;
        n.matrix = glm::make_mat4(src.matrix.data());  // both column-major
    }
    if (src.translation.size() == 3) n.pose.translation = glm::make_vec3(src.translation.data());
    if (src.scale.size() == 3) n.pose.scale = glm::make_vec3(src.scale.data());
    if (src.rotation.size() == 4)  // glTF: x, y, z, w
        n.pose.rotation = glm::normalize(glm::dquat(src.rotation[3], src.rotation[0], src.rotation[1], src.rotation[2]));
    const Json punctual = extension(src.extensions, "KHR_lights_punctual");
    if (punctual.is_object()) n.light = punctual.value("light", -1);
    n.media = extension(src.extensions, kMediaExtension);
    return n;
}

Camera readCamera(const tinygltf::Camera& src) {
    Camera c;
    c.orthographic = src.type == "orthographic";
    if (c.orthographic) {
        c.ymag = src.orthographic.ymag;
        c.znear = src.orthographic.znear;
        c.zfar = src.orthographic.zfar;
    } else {
        c.yfov = src.perspective.yfov;  // aspectRatio is ignored: the image size decides
        c.znear = src.perspective.znear;
        c.zfar = src.perspective.zfar;
    }
    return c;
}

// The displayed scene's roots: the default scene, else every parentless node (as Nimbus does).
void findRoots(const tinygltf::Model& model, Scene& scene) {
    if (model.defaultScene >= 0 && static_cast<std::size_t>(model.defaultScene) < model.scenes.size()) {
        scene.roots = model.scenes[static_cast<std::size_t>(model.defaultScene)].nodes;
    } else {
        for (std::size_t i = 0; i < scene.nodes.size(); ++i)
            if (scene.nodes[i].parent < 0) scene.roots.push_back(static_cast<int>(i));
    }
    scene.shown.assign(scene.nodes.size(), false);
    std::vector<int> stack = scene.roots;
    while (!stack.empty()) {
        const auto n = static_cast<std::size_t>(stack.back());
        stack.pop_back();
        if (n >= scene.nodes.size() || scene.shown[n]) continue;
        scene.shown[n] = true;
        stack.insert(stack.end(), scene.nodes[n].children.begin(), scene.nodes[n].children.end());
    }
}

void checkReferences(const Scene& scene, const std::string& file) {
    for (std::size_t i = 0; i < scene.nodes.size(); ++i) {
        const Node& n = scene.nodes[i];
        const std::string where = file + ": nodes[" + std::to_string(i) + "]";
        if (n.mesh >= static_cast<int>(scene.meshes.size())) throw SceneError(where + ": mesh out of range");
        if (n.camera >= static_cast<int>(scene.cameras.size())) throw SceneError(where + ": camera out of range");
        if (n.light >= static_cast<int>(scene.lights.size())) throw SceneError(where + ": light out of range");
        for (const int c : n.children)
            if (c < 0 || c >= static_cast<int>(scene.nodes.size())) throw SceneError(where + ": child out of range");
    }
    for (const Mesh& m : scene.meshes)
        for (const Primitive& p : m.primitives)
            if (p.material >= static_cast<int>(scene.materials.size())) throw SceneError(file + ": mesh \"" + m.name + "\": material out of range");
}

}  // namespace

Scene loadScene(const std::filesystem::path& file) {
    const std::string name = file.string();
    const auto shared = std::make_shared<const tinygltf::Model>(readModel(file));
    const tinygltf::Model& model = *shared;
    Scene scene;
    scene.path = file;
    scene.model = shared;
    for (const tinygltf::Node& n : model.nodes) scene.nodes.push_back(readNode(n));
    for (std::size_t i = 0; i < scene.nodes.size(); ++i)
        for (const int c : scene.nodes[i].children)
            if (c >= 0 && static_cast<std::size_t>(c) < scene.nodes.size()) scene.nodes[static_cast<std::size_t>(c)].parent = static_cast<int>(i);
    for (const tinygltf::Camera& c : model.cameras) scene.cameras.push_back(readCamera(c));
    for (const tinygltf::Material& m : model.materials) {
        Material material;
        const std::vector<double>& f = m.pbrMetallicRoughness.baseColorFactor;
        if (f.size() == 4) material.baseColorFactor = glm::vec4(glm::dvec4(f[0], f[1], f[2], f[3]));
        material.metallicFactor = static_cast<float>(m.pbrMetallicRoughness.metallicFactor);
        material.roughnessFactor = static_cast<float>(m.pbrMetallicRoughness.roughnessFactor);
        if (m.emissiveFactor.size() == 3) material.emissiveFactor = glm::vec3(glm::dvec3(m.emissiveFactor[0], m.emissiveFactor[1], m.emissiveFactor[2]));
        material.doubleSided = m.doubleSided;
        scene.materials.push_back(material);
    }
    scene.lights = readLights(extension(model.extensions, "KHR_lights_punctual"), name);
    scene.meshes = gltf::readMeshes(model, name);
    scene.channels = gltf::readChannels(model, name);
    scene.mediaRoot = extension(model.extensions, kMediaExtension);
    try {
        scene.environment.background = color3(scene.mediaRoot, "background", glm::vec3(0.0f));
        scene.environment.ambient = color3(scene.mediaRoot, "ambient", glm::vec3(0.0f));
    } catch (const std::exception& e) {
        throw SceneError(name + ": extensions." + kMediaExtension + "." + e.what());
    }
    findRoots(model, scene);
    checkReferences(scene, name);
    return scene;
}

}  // namespace mini
