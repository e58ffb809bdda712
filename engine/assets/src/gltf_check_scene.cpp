// Structural checks of the scene half of a glTF file: asset, extensions, cameras,
// KHR_lights_punctual lights, nodes (values and hierarchy), scenes and animations (gltf_checks.h).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <set>
#include <utility>

#include "gltf_accessor.h"
#include "gltf_check_util.h"
#include "gltf_checks.h"
#include "nimbus/assets/scene.h"

namespace nimbus::assets {
namespace {

constexpr double kPi = 3.14159265358979323846;

const Json& emptyArray() {
    static const Json empty = Json::array();
    return empty;
}

std::string nodeName(const Json& nodes, std::size_t i) { return describeObject("node", "nodes", i, nodes[i]); }

}  // namespace

void checkGltfAsset(const GltfCheckInput& in) {
    const JsonPlace root{&in.file, "glTF root", ""};
    const Json& asset = requiredObject(root, *in.root, "asset");
    // Top-level collections are arrays; checked once here so later lookups can rely on it.
    for (const char* key : {"accessors", "animations", "buffers", "bufferViews", "cameras", "images", "materials", "meshes",
                            "nodes", "samplers", "scenes", "skins", "textures"})
        optionalArray(root, *in.root, key);
    optionalObject(root, *in.root, "extensions");
    const JsonPlace place{&in.file, "asset", ""};
    const std::string version = requiredString(place, asset, "version");
    if (version.rfind("2.", 0) != 0) place.fail("version", "glTF version \"" + version + "\" is not supported (2.x only)");
    optionalString(place, asset, "minVersion");

    for (const char* key : {"extensionsUsed", "extensionsRequired"}) {
        const Json* list = optionalArray(root, *in.root, key);
        if (!list) continue;
        for (std::size_t i = 0; i < list->size(); ++i) {
            const std::string field = std::string(key) + "[" + std::to_string(i) + "]";
            if (!(*list)[i].is_string()) root.fail(field, "must be a string");
            if (std::string(key) == "extensionsRequired" && !isSupportedRequiredExtension((*list)[i].get<std::string>()))
                root.fail(field, "extension \"" + (*list)[i].get<std::string>() +
                                     "\" is required by the file but not supported by Nimbus");
        }
    }
    optionalIndex(root, *in.root, "scene", topLevelArray(*in.root, "scenes").size(), "scenes");
}

namespace {

// The root `fog` object (scene-format.md §2.1): every key known, every value in range.
void checkFog(const JsonPlace& parent, const Json& media) {
    const Json* fog = optionalObject(parent, media, "fog");
    if (!fog) return;
    const JsonPlace place = parent.nested("fog");
    const std::array<std::string, 7> known = {"mode", "color", "density", "start", "end", "base", "falloff"};
    for (const auto& item : fog->items())
        if (std::find(known.begin(), known.end(), item.key()) == known.end())
            place.fail(item.key(), "unknown key (fog has mode, color, density, start, end, base, falloff)");
    const auto mode = optionalEnum(place, *fog, "mode", {"exp", "exp2", "linear", "height"});
    if (!mode) place.fail("mode", "is required: \"exp\", \"exp2\", \"linear\" or \"height\"");
    optionalNumberArray(place, *fog, "color", 3, 0.0, kHuge);
    optionalNumber(place, *fog, "density", 0.0, kHuge);
    const double start = optionalNumber(place, *fog, "start", -kHuge, kHuge).value_or(0.0);
    const auto end = optionalNumber(place, *fog, "end", -kHuge, kHuge);
    optionalNumber(place, *fog, "base", -kHuge, kHuge);
    optionalNumber(place, *fog, "falloff", 0.0, kHuge);
    if (*mode == "linear" && !end) place.fail("end", "is required for linear fog");
    if (end && *end <= start)
        place.fail("end", "must be greater than start (" + Json(start).dump() + "), not " + Json(*end).dump());
}

void checkEnvironment(const GltfCheckInput& in) {
    const JsonPlace root{&in.file, "glTF root", ""};
    const Json* extensions = optionalObject(root, *in.root, "extensions");
    if (!extensions) return;
    const Json* media = optionalObject(root.nested("extensions"), *extensions, kMediaExtension);
    if (!media) return;
    // Every key of the root object is the engine's; other tools' data belongs under `extras`.
    const JsonPlace place{&in.file, std::string("root extension ") + kMediaExtension, ""};
    const std::array<std::string, 5> known = {"background", "ambient", "fog", "scattering", "extras"};
    for (const auto& item : media->items())
        if (std::find(known.begin(), known.end(), item.key()) == known.end())
            place.fail(item.key(), "unknown key (the root object has background, ambient, fog, scattering and extras)");
    optionalNumberArray(place, *media, "background", 3, 0.0, kHuge);
    optionalNumberArray(place, *media, "ambient", 3, 0.0, kHuge);
    optionalEnum(place, *media, "scattering", {"multiple", "single"});
    checkFog(place, *media);
}

void checkLights(const GltfCheckInput& in) {
    const JsonPlace root{&in.file, "glTF root", "extensions."};
    const Json* extensions = findMember(*in.root, "extensions");
    if (!extensions || !extensions->is_object()) return;
    const Json* punctual = optionalObject(root, *extensions, "KHR_lights_punctual");
    if (!punctual) return;
    const Json* lights = optionalArray(root.nested("KHR_lights_punctual"), *punctual, "lights");
    if (!lights) return;
    for (std::size_t i = 0; i < lights->size(); ++i) {
        const Json& l = (*lights)[i];
        const JsonPlace place{&in.file, describeObject("light", "KHR_lights_punctual.lights", i, l), ""};
        if (!l.is_object()) place.fail("", "must be a JSON object");
        const auto type = optionalEnum(place, l, "type", {"directional", "point", "spot"});
        if (!type) place.fail("type", "is required but missing");
        optionalString(place, l, "name");
        optionalNumberArray(place, l, "color", 3, 0.0, kHuge);
        optionalNumber(place, l, "intensity", 0.0, kHuge);
        if (const auto range = optionalNumber(place, l, "range", -kHuge, kHuge); range && *range <= 0.0)
            place.fail("range", "must be > 0 (leave it out for an infinite range), not " + Json(*range).dump());
        const Json* spot = optionalObject(place, l, "spot");
        if (*type == "spot" && !spot) place.fail("spot", "is required for a spot light");
        if (*type != "spot" || !spot) continue;
        const JsonPlace sp = place.nested("spot");
        const double inner = optionalNumber(sp, *spot, "innerConeAngle", 0.0, kPi / 2).value_or(0.0);
        const double outer = optionalNumber(sp, *spot, "outerConeAngle", 0.0, kPi / 2).value_or(kPi / 4);
        if (!(inner < outer))
            sp.fail("innerConeAngle", "must be smaller than outerConeAngle (" + Json(inner).dump() + " >= " +
                                          Json(outer).dump() + ")");
    }
}

void checkCameras(const GltfCheckInput& in) {
    forEachObject(in, "cameras", "camera", [&](std::size_t, const Json& c, const JsonPlace& place) {
        const auto type = optionalEnum(place, c, "type", {"perspective", "orthographic"});
        if (!type) place.fail("type", "is required but missing");
        if (*type == "perspective") {
            const Json& p = requiredObject(place, c, "perspective");
            const JsonPlace pp = place.nested("perspective");
            const double yfov = requiredNumber(pp, p, "yfov", -kHuge, kHuge);
            if (!(yfov > 0.0 && yfov < kPi)) pp.fail("yfov", "must be in (0, pi) radians, not " + Json(yfov).dump());
            const double znear = requiredNumber(pp, p, "znear", -kHuge, kHuge);
            if (!(znear > 0.0)) pp.fail("znear", "must be > 0, not " + Json(znear).dump());
            if (const auto zfar = optionalNumber(pp, p, "zfar", -kHuge, kHuge); zfar && !(*zfar > znear))
                pp.fail("zfar", "must be greater than znear (" + Json(*zfar).dump() + " <= " + Json(znear).dump() + ")");
            if (const auto aspect = optionalNumber(pp, p, "aspectRatio", -kHuge, kHuge); aspect && !(*aspect > 0.0))
                pp.fail("aspectRatio", "must be > 0, not " + Json(*aspect).dump());
        } else {
            const Json& o = requiredObject(place, c, "orthographic");
            const JsonPlace op = place.nested("orthographic");
            for (const char* key : {"xmag", "ymag"})
                if (requiredNumber(op, o, key, -kHuge, kHuge) == 0.0) op.fail(key, "must not be zero");
            const double znear = requiredNumber(op, o, "znear", 0.0, kHuge);
            const double zfar = requiredNumber(op, o, "zfar", -kHuge, kHuge);
            if (!(zfar > znear))
                op.fail("zfar", "must be greater than znear (" + Json(zfar).dump() + " <= " + Json(znear).dump() + ")");
        }
    });
}

void checkNodeValues(const GltfCheckInput& in) {
    const std::size_t meshes = topLevelArray(*in.root, "meshes").size();
    const std::size_t cameras = topLevelArray(*in.root, "cameras").size();
    const std::size_t skins = topLevelArray(*in.root, "skins").size();
    const std::size_t lights = punctualLights(*in.root).size();
    forEachObject(in, "nodes", "node", [&](std::size_t, const Json& n, const JsonPlace& place) {
        optionalString(place, n, "name");
        optionalIndex(place, n, "mesh", meshes, "meshes");
        optionalIndex(place, n, "camera", cameras, "cameras");
        optionalIndex(place, n, "skin", skins, "skins");
        const std::vector<double> m = optionalNumberArray(place, n, "matrix", 16, -kHuge, kHuge);
        if (!m.empty()) {
            for (const char* key : {"translation", "rotation", "scale"})
                if (n.contains(key)) place.fail("matrix", std::string("cannot be combined with ") + key + " (glTF: matrix or TRS)");
            if (m[3] != 0.0 || m[7] != 0.0 || m[11] != 0.0 || m[15] != 1.0)
                place.fail("matrix", "is not an affine transform (its last row must be 0, 0, 0, 1)");
        }
        optionalNumberArray(place, n, "translation", 3, -kHuge, kHuge);
        optionalNumberArray(place, n, "scale", 3, -kHuge, kHuge);
        const std::vector<double> q = optionalNumberArray(place, n, "rotation", 4, -1.0, 1.0);
        if (!q.empty()) {
            const double length = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
            if (std::abs(length - 1.0) > 1e-2)
                place.fail("rotation", "is not a unit quaternion (length " + Json(length).dump() + ")");
        }
        optionalArray(place, n, "weights");
        const Json* ext = optionalObject(place, n, "extensions");
        if (!ext) return;
        const JsonPlace ep = place.nested("extensions");
        if (const Json* punctual = optionalObject(ep, *ext, "KHR_lights_punctual"))
            requiredIndex(ep.nested("KHR_lights_punctual"), *punctual, "light", lights, "KHR_lights_punctual lights");
    });
}

// Every node has at most one parent and the hierarchy has no cycle; scene roots are roots.
void checkHierarchy(const GltfCheckInput& in) {
    const Json& nodes = topLevelArray(*in.root, "nodes");
    std::vector<std::int64_t> parent(nodes.size(), -1);
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        const JsonPlace place{&in.file, nodeName(nodes, i), ""};
        const Json* children = optionalArray(place, nodes[i], "children");
        if (!children) continue;
        for (std::size_t k = 0; k < children->size(); ++k) {
            const std::string field = "children[" + std::to_string(k) + "]";
            checkIndexValue(place, field, (*children)[k], nodes.size(), "nodes");
            const auto child = (*children)[k].get<std::size_t>();
            if (child == i) place.fail(field, "a node cannot be its own child");
            if (parent[child] >= 0)
                place.fail(field, nodeName(nodes, child) + " already has a parent, " +
                                      nodeName(nodes, static_cast<std::size_t>(parent[child])) +
                                      " (a node may have only one parent)");
            parent[child] = static_cast<std::int64_t>(i);
        }
    }
    // With one parent each, a cycle is a parent chain that never reaches a root.
    std::vector<int> state(nodes.size(), 0);  // 0 unseen, 1 on the current chain, 2 reaches a root
    for (std::size_t start = 0; start < nodes.size(); ++start) {
        std::vector<std::size_t> chain;
        std::int64_t n = static_cast<std::int64_t>(start);
        while (n >= 0 && state[static_cast<std::size_t>(n)] == 0) {
            state[static_cast<std::size_t>(n)] = 1;
            chain.push_back(static_cast<std::size_t>(n));
            n = parent[static_cast<std::size_t>(n)];
        }
        if (n >= 0 && state[static_cast<std::size_t>(n)] == 1) {
            std::string path;
            for (std::size_t c : chain) path += (path.empty() ? "" : " -> ") + ("nodes[" + std::to_string(c) + "]");
            const JsonPlace place{&in.file, nodeName(nodes, static_cast<std::size_t>(n)), ""};
            place.fail("children", "the node hierarchy has a cycle (child -> parent: " + path + ")");
        }
        for (std::size_t c : chain) state[c] = 2;
    }
    forEachObject(in, "scenes", "scene", [&](std::size_t, const Json& s, const JsonPlace& place) {
        const Json* roots = optionalArray(place, s, "nodes");
        if (!roots) return;
        std::set<std::size_t> seen;
        for (std::size_t k = 0; k < roots->size(); ++k) {
            const std::string field = "nodes[" + std::to_string(k) + "]";
            checkIndexValue(place, field, (*roots)[k], nodes.size(), "nodes");
            const auto root = (*roots)[k].get<std::size_t>();
            if (!seen.insert(root).second) place.fail(field, nodeName(nodes, root) + " is listed twice");
            if (parent[root] >= 0)
                place.fail(field, nodeName(nodes, root) + " is not a root node (its parent is " +
                                      nodeName(nodes, static_cast<std::size_t>(parent[root])) + ")");
        }
    });
}

void checkAnimations(const GltfCheckInput& in) {
    const Json& nodes = topLevelArray(*in.root, "nodes");
    const Json& accessors = topLevelArray(*in.root, "accessors");
    forEachObject(in, "animations", "animation", [&](std::size_t, const Json& anim, const JsonPlace& place) {
        const Json* samplers = optionalArray(place, anim, "samplers");
        const Json* channels = optionalArray(place, anim, "channels");
        if (!samplers || samplers->empty()) place.fail("samplers", "an animation needs at least one sampler");
        if (!channels || channels->empty()) place.fail("channels", "an animation needs at least one channel");
        for (std::size_t s = 0; s < samplers->size(); ++s) {
            const JsonPlace sp{place.file, place.object, "samplers[" + std::to_string(s) + "]."};
            const Json& sampler = (*samplers)[s];
            if (!sampler.is_object()) place.fail("samplers[" + std::to_string(s) + "]", "must be a JSON object");
            const int input = requiredIndex(sp, sampler, "input", accessors.size(), "accessors");
            requiredIndex(sp, sampler, "output", accessors.size(), "accessors");
            optionalEnum(sp, sampler, "interpolation", {"LINEAR", "STEP", "CUBICSPLINE"});
            const Json& a = accessors[static_cast<std::size_t>(input)];
            if (a["type"] != "SCALAR" || a["componentType"] != 5126)
                sp.fail("input", "accessors[" + std::to_string(input) + "] must be SCALAR FLOAT (key times in seconds)");
        }
        std::set<std::pair<std::int64_t, std::string>> targets;
        for (std::size_t c = 0; c < channels->size(); ++c) {
            const JsonPlace cp{place.file, place.object, "channels[" + std::to_string(c) + "]."};
            const Json& channel = (*channels)[c];
            if (!channel.is_object()) place.fail("channels[" + std::to_string(c) + "]", "must be a JSON object");
            const int s = requiredIndex(cp, channel, "sampler", samplers->size(), "samplers in this animation");
            const Json& target = requiredObject(cp, channel, "target");
            const JsonPlace tp = cp.nested("target");
            const auto node = optionalIndex(tp, target, "node", nodes.size(), "nodes");
            const auto path = optionalEnum(tp, target, "path", {"translation", "rotation", "scale", "weights"});
            if (!path) tp.fail("path", "is required but missing");
            if (!node || *path == "weights") continue;  // ignored at load (with a warning for weights)
            if (nodes[static_cast<std::size_t>(*node)].contains("matrix"))
                tp.fail("node", nodeName(nodes, static_cast<std::size_t>(*node)) +
                                    " is given as a matrix, which glTF does not allow to animate");
            if (!targets.emplace(*node, *path).second)
                tp.fail("path", "a second channel animates " + *path + " of " + nodeName(nodes, static_cast<std::size_t>(*node)));

            const Json& sampler = (*samplers)[static_cast<std::size_t>(s)];
            const JsonPlace sp{place.file, place.object, "samplers[" + std::to_string(s) + "]."};
            const Json& input = accessors[sampler["input"].get<std::size_t>()];
            const std::size_t outputIndex = sampler["output"].get<std::size_t>();
            const Json& output = accessors[outputIndex];
            const std::string type = output["type"].get<std::string>();
            const int componentType = output["componentType"].get<int>();
            const bool normalized = output.value("normalized", false);
            const bool ok = *path == "rotation"
                                ? type == "VEC4" && (componentType == 5126 || (normalized && componentType != 5125))
                                : type == "VEC3" && componentType == 5126;
            if (!ok)
                sp.fail("output", "accessors[" + std::to_string(outputIndex) + "] is " + type + " " +
                                      componentTypeName(componentType) + (normalized ? " normalized" : "") + ", but " +
                                      *path + " needs " + (*path == "rotation" ? "VEC4 FLOAT or normalized integers" : "VEC3 FLOAT"));
            const bool cubic = sampler.value("interpolation", "LINEAR") == "CUBICSPLINE";
            const std::int64_t keys = input["count"].get<std::int64_t>();
            const std::int64_t expected = cubic ? 3 * keys : keys;
            if (output["count"].get<std::int64_t>() != expected)
                sp.fail("output", "has " + output["count"].dump() + " values for " + std::to_string(keys) + " key times (expected " +
                                      std::to_string(expected) + (cubic ? ": in-tangent, value, out-tangent per key)" : ")"));
        }
    });
}

}  // namespace

const Json& topLevelArray(const Json& root, const char* key) {
    const Json* v = findMember(root, key);
    return v && v->is_array() ? *v : emptyArray();
}

const Json& punctualLights(const Json& root) {
    const Json* ext = findMember(root, "extensions");
    const Json* punctual = ext ? findMember(*ext, "KHR_lights_punctual") : nullptr;
    const Json* lights = punctual ? findMember(*punctual, "lights") : nullptr;
    return lights && lights->is_array() ? *lights : emptyArray();
}

bool isSupportedRequiredExtension(const std::string& name) {
    return name == "KHR_lights_punctual" || name == "KHR_texture_transform" || name == kMediaExtension;
}

void checkGltfSceneGraph(const GltfCheckInput& in) {
    checkEnvironment(in);
    checkLights(in);
    checkCameras(in);
    checkNodeValues(in);
    checkHierarchy(in);
    checkAnimations(in);
}

}  // namespace nimbus::assets
