// loadScene: read the file, check its structure, let tinygltf load buffers and images (decoded
// with OpenImageIO), then build the Scene while checking the data itself. Nothing is returned
// unless everything passed, so a Scene that exists is complete and in range.
#include <cmath>
#include <cstring>

#include <glm/gtc/type_ptr.hpp>

#include "document.h"
#include "gltf_accessor.h"
#include "gltf_animation_builder.h"
#include "gltf_checks.h"
#include "gltf_container.h"
#include "gltf_image_decoder.h"
#include "gltf_mesh_builder.h"
#include "json_fields.h"
#include "nimbus/assets/scene.h"
#include "nimbus/assets/scene_queries.h"
#include "nimbus/base/error.h"
#include "nimbus/base/log.h"

namespace nimbus::assets {
namespace {

// ---- tinygltf file access ------------------------------------------------------------------
// tinygltf looks for a relative URI next to the glTF file and then in the current directory; the
// second would make loading depend on where the program runs, so only the first is allowed. Its
// default path expansion (wordexp) is replaced by the identity: URIs are not shell words.
struct FileAccess {
    std::string baseDirectory;  // with a trailing separator
};

bool fileExistsBesideGltf(const std::string& path, void* user) {
    const auto& access = *static_cast<const FileAccess*>(user);
    if (path.rfind(access.baseDirectory, 0) != 0) return false;
    std::error_code ec;
    return std::filesystem::is_regular_file(path, ec);
}

std::string expandNothing(const std::string& path, void*) { return path; }

// tinygltf's messages end lines with '\n' and may quote whole data URIs: keep one short line.
std::string oneLine(std::string text) {
    for (char& c : text)
        if (c == '\n' || c == '\r') c = ' ';
    while (!text.empty() && text.back() == ' ') text.pop_back();
    if (text.size() > 300) text = text.substr(0, 297) + "...";
    return text;
}

tinygltf::Model loadWithTinyGltf(const GltfSource& src, const std::string& name, const std::filesystem::path& baseDirectory) {
    tinygltf::TinyGLTF loader;
    ImageDecodeContext images{&name, &src.json, {}};
    loader.SetImageLoader(&decodeGltfImage, &images);
    FileAccess access{(baseDirectory / "").string()};
    loader.SetFsCallbacks({&fileExistsBesideGltf, &expandNothing, &tinygltf::ReadWholeFile, &tinygltf::WriteWholeFile, &access});

    tinygltf::Model model;
    std::string err, warn;
    const auto size = static_cast<unsigned int>(src.bytes.size());
    const bool ok = src.binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, src.bytes.data(), size, baseDirectory.string())
                               : loader.LoadASCIIFromString(&model, &err, &warn, reinterpret_cast<const char*>(src.bytes.data()),
                                                            size, baseDirectory.string());
    if (!warn.empty()) log::debug(name + ": tinygltf: " + oneLine(warn));
    if (!images.failure.empty()) throw InputError(images.failure);
    if (!ok) throwInputError(name, "", "", "tinygltf refused the file: " + oneLine(err));
    return model;
}

// ---- scene parts ---------------------------------------------------------------------------

const Json& jsonElement(const Json& root, const char* array, std::size_t i) { return root[array][i]; }

std::vector<Image> takeImages(tinygltf::Model& model, const Json& root, const std::string& name) {
    std::vector<Image> images(model.images.size());
    for (std::size_t i = 0; i < model.images.size(); ++i) {
        tinygltf::Image& src = model.images[i];
        const std::size_t expected = static_cast<std::size_t>(std::max(src.width, 0)) * static_cast<std::size_t>(std::max(src.height, 0)) * 4;
        if (src.image.empty() || src.image.size() != expected || src.component != 4 || src.bits != 8)
            throwInputError(name, describeObject("image", "images", i, jsonElement(root, "images", i)), "uri",
                            "the image could not be read");
        images[i].name = !src.name.empty() ? src.name : src.uri;
        images[i].width = src.width;
        images[i].height = src.height;
        images[i].rgba8 = std::move(src.image);  // pixels live in the Scene; the model keeps uri / bufferView
        src.image.clear();
    }
    return images;
}

Wrap wrapFromGl(int mode) {
    if (mode == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE) return Wrap::ClampToEdge;
    if (mode == TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT) return Wrap::MirroredRepeat;
    return Wrap::Repeat;
}

std::vector<Texture> buildTextures(const tinygltf::Model& model, const Json& root) {
    std::vector<Texture> textures(model.textures.size());
    for (std::size_t i = 0; i < model.textures.size(); ++i) {
        const tinygltf::Texture& src = model.textures[i];
        Texture& t = textures[i];
        t.image = src.source;
        if (t.image < 0) {  // EXT_texture_webp may carry the only source
            const Json& j = jsonElement(root, "textures", i);
            if (j.contains("extensions") && j["extensions"].contains("EXT_texture_webp"))
                t.image = j["extensions"]["EXT_texture_webp"].value("source", -1);
        }
        if (src.sampler < 0) continue;
        const tinygltf::Sampler& s = model.samplers[static_cast<std::size_t>(src.sampler)];
        t.wrapS = wrapFromGl(s.wrapS);
        t.wrapT = wrapFromGl(s.wrapT);
        t.magFilter = s.magFilter == TINYGLTF_TEXTURE_FILTER_NEAREST ? Filter::Nearest : Filter::Linear;
        switch (s.minFilter) {
            case TINYGLTF_TEXTURE_FILTER_NEAREST: t.minFilter = Filter::Nearest; t.mipmaps = false; break;
            case TINYGLTF_TEXTURE_FILTER_LINEAR: t.minFilter = Filter::Linear; t.mipmaps = false; break;
            case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_NEAREST:
            case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_LINEAR: t.minFilter = Filter::Nearest; t.mipmaps = true; break;
            default: t.minFilter = Filter::Linear; t.mipmaps = true; break;  // mipmapped linear, or left to us
        }
    }
    return textures;
}

// A textureInfo as checked by checkMaterials: index, texCoord and KHR_texture_transform folded into
// one affine map (the extension's translation · rotation · scale).
TextureRef readTextureRef(const Json& owner, const char* key) {
    TextureRef ref;
    if (!owner.contains(key)) return ref;
    const Json& info = owner[key];
    ref.texture = info["index"].get<int>();
    ref.texCoord = info.value("texCoord", 0);
    if (!info.contains("extensions") || !info["extensions"].contains("KHR_texture_transform")) return ref;
    const Json& t = info["extensions"]["KHR_texture_transform"];
    const double ox = t.contains("offset") ? t["offset"][0].get<double>() : 0.0, oy = t.contains("offset") ? t["offset"][1].get<double>() : 0.0;
    const double sx = t.contains("scale") ? t["scale"][0].get<double>() : 1.0, sy = t.contains("scale") ? t["scale"][1].get<double>() : 1.0;
    const double r = t.value("rotation", 0.0);
    ref.row0 = glm::vec3(glm::dvec3(std::cos(r) * sx, -std::sin(r) * sy, ox));
    ref.row1 = glm::vec3(glm::dvec3(std::sin(r) * sx, std::cos(r) * sy, oy));
    ref.texCoord = t.value("texCoord", ref.texCoord);
    return ref;
}

std::vector<Material> buildMaterials(const Json& root, const std::vector<Texture>& textures, const std::string& name) {
    const Json& array = topLevelArray(root, "materials");
    std::vector<Material> materials(array.size());
    std::vector<std::string> undrawn;  // materials with normal or occlusion textures
    for (std::size_t i = 0; i < array.size(); ++i) {
        const Json& src = array[i];
        Material& m = materials[i];
        m.name = src.value("name", "");
        const Json pbr = src.value("pbrMetallicRoughness", Json::object());
        if (pbr.contains("baseColorFactor")) {
            const Json& f = pbr["baseColorFactor"];
            m.baseColorFactor = glm::vec4(glm::dvec4(f[0].get<double>(), f[1].get<double>(), f[2].get<double>(), f[3].get<double>()));
        }
        m.baseColorTexture = readTextureRef(pbr, "baseColorTexture");
        m.metallicFactor = static_cast<float>(pbr.value("metallicFactor", 1.0));
        m.roughnessFactor = static_cast<float>(pbr.value("roughnessFactor", 1.0));
        m.metallicRoughnessTexture = readTextureRef(pbr, "metallicRoughnessTexture");
        if (src.contains("emissiveFactor")) {
            const Json& e = src["emissiveFactor"];
            m.emissiveFactor = glm::vec3(glm::dvec3(e[0].get<double>(), e[1].get<double>(), e[2].get<double>()));
        }
        m.emissiveTexture = readTextureRef(src, "emissiveTexture");
        const std::string mode = src.value("alphaMode", std::string("OPAQUE"));
        m.alphaMode = mode == "MASK" ? AlphaMode::Mask : mode == "BLEND" ? AlphaMode::Blend : AlphaMode::Opaque;
        m.alphaCutoff = static_cast<float>(src.value("alphaCutoff", 0.5));
        m.doubleSided = src.value("doubleSided", false);
        const std::string object = describeObject("material", "materials", i, src);
        for (const auto& [ref, field] : {std::pair{&m.baseColorTexture, "pbrMetallicRoughness.baseColorTexture"},
                                         std::pair{&m.metallicRoughnessTexture, "pbrMetallicRoughness.metallicRoughnessTexture"},
                                         std::pair{&m.emissiveTexture, "emissiveTexture"}})
            if (ref->present() && textures[static_cast<std::size_t>(ref->texture)].image < 0)
                throwInputError(name, object, field, "textures[" + std::to_string(ref->texture) + "] has no image Nimbus can decode");
        if (src.contains("normalTexture") || src.contains("occlusionTexture")) undrawn.push_back(object);
    }
    if (!undrawn.empty()) {
        std::string list;
        for (const std::string& o : undrawn) list += (list.empty() ? "" : ", ") + o;
        log::warn(name + ": normal and occlusion textures are not drawn (docs/scene-format.md §4.1): " + list);
    }
    return materials;
}

std::vector<Camera> buildCameras(const tinygltf::Model& model) {
    std::vector<Camera> cameras(model.cameras.size());
    for (std::size_t i = 0; i < model.cameras.size(); ++i) {
        const tinygltf::Camera& src = model.cameras[i];
        Camera& c = cameras[i];
        c.name = src.name;
        if (src.type == "orthographic") {
            c.projection = Projection::Orthographic;
            c.xmag = src.orthographic.xmag;
            c.ymag = src.orthographic.ymag;
            c.znear = src.orthographic.znear;
            c.zfar = src.orthographic.zfar;
        } else {
            c.projection = Projection::Perspective;
            c.yfov = src.perspective.yfov;
            c.aspectRatio = src.perspective.aspectRatio;
            c.znear = src.perspective.znear;
            c.zfar = src.perspective.zfar;
        }
    }
    return cameras;
}

// KHR_lights_punctual, from the root extension's "lights" array (checked in gltf_check_scene.cpp);
// read from the JSON rather than tinygltf's Model::lights so defaults are the spec's, not the reader's.
std::vector<Light> buildLights(const Json& root) {
    const Json& lights = punctualLights(root);
    std::vector<Light> out(lights.size());
    for (std::size_t i = 0; i < lights.size(); ++i) {
        const Json& l = lights[i];
        Light& light = out[i];
        light.name = l.value("name", "");
        const std::string type = l["type"].get<std::string>();
        light.type = type == "point" ? LightType::Point : type == "spot" ? LightType::Spot : LightType::Directional;
        if (l.contains("color")) light.color = glm::vec3(glm::dvec3(l["color"][0].get<double>(), l["color"][1].get<double>(), l["color"][2].get<double>()));
        light.intensity = static_cast<float>(l.value("intensity", 1.0));
        light.range = l.value("range", 0.0);
        if (light.type == LightType::Spot) {
            light.innerConeAngle = l["spot"].value("innerConeAngle", 0.0);
            light.outerConeAngle = l["spot"].value("outerConeAngle", 0.7853981633974483);
        }
    }
    return out;
}

std::vector<Node> buildNodes(const tinygltf::Model& model, const Json& root) {
    std::vector<Node> nodes(model.nodes.size());
    for (std::size_t i = 0; i < model.nodes.size(); ++i) {
        const tinygltf::Node& src = model.nodes[i];
        Node& n = nodes[i];
        n.name = src.name;
        n.children = src.children;
        n.mesh = src.mesh;
        n.camera = src.camera;
        if (src.matrix.size() == 16) {
            n.hasMatrix = true;
            n.matrix = glm::make_mat4(src.matrix.data());  // glTF and GLM are both column-major
        }
        if (src.translation.size() == 3) n.translation = glm::make_vec3(src.translation.data());
        if (src.scale.size() == 3) n.scale = glm::make_vec3(src.scale.data());
        if (src.rotation.size() == 4)  // glTF stores x, y, z, w; checked to be within 1% of unit length
            n.rotation = glm::normalize(glm::dquat(src.rotation[3], src.rotation[0], src.rotation[1], src.rotation[2]));
        const Json& j = jsonElement(root, "nodes", i);
        if (j.contains("extensions")) {
            n.extensions = j["extensions"];
            if (n.extensions.contains("KHR_lights_punctual")) n.light = n.extensions["KHR_lights_punctual"]["light"].get<int>();
        }
    }
    for (std::size_t i = 0; i < nodes.size(); ++i)
        for (const int c : nodes[i].children) nodes[static_cast<std::size_t>(c)].parent = static_cast<int>(i);
    return nodes;
}

std::vector<int> findRootNodes(const Json& root, const std::vector<Node>& nodes) {
    std::vector<int> roots;
    if (root.contains("scene")) {
        const Json& scene = root["scenes"][root["scene"].get<std::size_t>()];
        if (scene.contains("nodes")) roots = scene["nodes"].get<std::vector<int>>();
        return roots;
    }
    for (std::size_t i = 0; i < nodes.size(); ++i)
        if (nodes[i].parent < 0) roots.push_back(static_cast<int>(i));
    return roots;
}

// Checked by checkFog; absent values take the defaults of scene-format.md §2.1.
Fog readFog(const Json& media) {
    Fog fog;
    if (!media.contains("fog")) return fog;
    const Json& f = media["fog"];
    const std::string mode = f["mode"].get<std::string>();
    fog.mode = mode == "exp" ? FogMode::Exp : mode == "exp2" ? FogMode::Exp2 : mode == "linear" ? FogMode::Linear : FogMode::Height;
    if (f.contains("color")) fog.color = glm::dvec3(f["color"][0].get<double>(), f["color"][1].get<double>(), f["color"][2].get<double>());
    fog.density = f.value("density", 0.0);
    fog.start = f.value("start", 0.0);
    fog.hasEnd = f.contains("end");
    fog.end = f.value("end", 0.0);
    fog.base = f.value("base", 0.0);
    fog.falloff = f.value("falloff", 0.0);
    return fog;
}

glm::vec3 readColor(const Json& object, const char* key) {
    if (!object.contains(key)) return glm::vec3(0.0f);
    const Json& c = object[key];
    return glm::vec3(glm::dvec3(c[0].get<double>(), c[1].get<double>(), c[2].get<double>()));
}

bool hasLightInScene(const Scene& scene) {
    const std::vector<bool> in = nodesInScene(scene);
    for (std::size_t i = 0; i < scene.nodes.size(); ++i)
        if (in[i] && scene.nodes[i].light >= 0) return true;
    return false;
}

// Values that are finite one by one can still overflow when composed (a scale of 1e200 twice).
void checkWorldTransformsFinite(const Scene& scene, const Json& root) {
    const std::vector<glm::dmat4> world = computeWorldTransforms(scene, 0.0);
    for (std::size_t i = 0; i < world.size(); ++i)
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r)
                if (!std::isfinite(world[i][c][r]))
                    throwInputError(scene.displayName(), describeObject("node", "nodes", i, jsonElement(root, "nodes", i)),
                                    scene.nodes[i].hasMatrix ? "matrix" : "translation/rotation/scale",
                                    "the world transform is not finite (values too large)");
}


Scene loadSceneFromSource(GltfSource src, const std::filesystem::path& file) {
    const std::string name = file.string();
    std::error_code ec;
    const std::filesystem::path absolute = std::filesystem::absolute(file, ec);
    const std::filesystem::path baseDirectory = (ec ? file : absolute).parent_path();

    checkGltfStructure({&src.json, name, baseDirectory, src.binary, src.binChunkSize});

    auto document = std::make_shared<Document>();
    document->path = file;
    document->displayName = name;
    document->model = loadWithTinyGltf(src, name, baseDirectory);
    document->json = std::move(src.json);
    tinygltf::Model& model = document->model;
    const Json& root = document->json;

    Scene scene;
    scene.path = file;
    scene.images = takeImages(model, root, name);
    scene.textures = buildTextures(model, root);
    scene.materials = buildMaterials(root, scene.textures, name);
    scene.meshes = buildMeshes(model, root, name);
    scene.cameras = buildCameras(model);
    scene.lights = buildLights(root);
    scene.nodes = buildNodes(model, root);
    scene.rootNodes = findRootNodes(root, scene.nodes);
    scene.animations = buildAnimations(model, root, name);
    if (root.contains("extensions")) {
        scene.extensions = root["extensions"];
        if (scene.extensions.contains(kMediaExtension)) {
            const Json& media = scene.extensions[kMediaExtension];
            scene.environment.background = readColor(media, "background");
            scene.environment.ambient = readColor(media, "ambient");
            scene.environment.fog = readFog(media);
            if (media.value("scattering", std::string("multiple")) == "single") scene.environment.scattering = Scattering::Single;
        }
    }
    // A plain glTF file without lights: the default sun alone would leave every face turned from it
    // black, so it also gets the documented default ambient (docs/scene-format.md §4).
    if (!scene.extensions.contains(kMediaExtension) && !hasLightInScene(scene)) {
        scene.environment.ambient = glm::vec3(kDefaultAmbient);
        scene.environment.defaultAmbient = true;
    }
    scene.document = document;
    checkWorldTransformsFinite(scene, root);
    return scene;
}

}  // namespace

std::string Scene::displayName() const { return document ? document->displayName : path.string(); }

Scene loadScene(const std::filesystem::path& file) { return loadSceneFromSource(readGltfSource(file, file.string()), file); }

Scene loadSceneFromMemory(std::vector<unsigned char> bytes, const std::filesystem::path& file) {
    return loadSceneFromSource(parseGltfBytes(std::move(bytes), file.string()), file);
}

}  // namespace nimbus::assets
