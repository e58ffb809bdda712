// Structural checks of the data half of a glTF file: buffers, buffer views, accessors, images,
// samplers, textures, materials, meshes and skins (see gltf_checks.h).
#include <cstdint>
#include <set>

#include "gltf_accessor.h"
#include "gltf_checks.h"
#include "gltf_check_util.h"
#include "gltf_uri.h"
#include "nimbus/base/error.h"

namespace nimbus::assets {
namespace {

constexpr std::int64_t kMaxBytes = 0xFFFFFFFFll;          // 32-bit sizes, as GLB and tinygltf use
constexpr std::int64_t kMaxAccessorCount = 1ll << 28;     // "absurd" beyond this

void checkExternalFile(const GltfCheckInput& in, const JsonPlace& place, const std::string& uri,
                       std::optional<std::int64_t> expectedBytes) {
    if (hasMalformedPercentEscape(uri)) place.fail("uri", "malformed percent-encoding in \"" + uri + "\"");
    if (uri.find("://") != std::string::npos || std::filesystem::path(decodeUriPath(uri)).is_absolute())
        place.fail("uri", "only data URIs and paths relative to the glTF file are supported, not \"" + uri + "\"");
    // A scene reads its own folder and below, never a path a file names elsewhere ("../../...").
    const std::filesystem::path relative = std::filesystem::path(decodeUriPath(uri)).lexically_normal();
    if (!relative.empty() && *relative.begin() == "..")
        place.fail("uri", "\"" + decodeUriPath(uri) + "\" lies outside the glTF file's folder (only files in it or below it are read)");
    const std::filesystem::path path = resolveUri(in.baseDirectory, uri);
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        place.fail("uri", "no such file \"" + decodeUriPath(uri) + "\" next to the glTF file");
    if (expectedBytes) {
        const std::uintmax_t size = std::filesystem::file_size(path, ec);
        if (ec) place.fail("uri", "cannot read the size of \"" + decodeUriPath(uri) + "\"");
        if (size != static_cast<std::uintmax_t>(*expectedBytes))
            place.fail("byteLength", "file \"" + decodeUriPath(uri) + "\" has " + std::to_string(size) +
                                         " bytes but byteLength says " + std::to_string(*expectedBytes));
    }
}

void checkDataUri(const JsonPlace& place, const std::string& uri, std::optional<std::int64_t> expectedBytes) {
    if (!isDecodableDataUri(uri))
        place.fail("uri", "unsupported data URI media type \"" + dataUriMediaType(uri) +
                              "\" (base64 application/octet-stream, application/gltf-buffer, image/png or image/jpeg)");
    const DataUriSize size = dataUriDecodedSize(uri);
    if (!size.bytes) place.fail("uri", size.problem);
    if (*size.bytes == 0) place.fail("uri", "the data URI holds no data");
    if (expectedBytes && *size.bytes != static_cast<std::size_t>(*expectedBytes))
        place.fail("byteLength", "the data URI holds " + std::to_string(*size.bytes) + " bytes but byteLength says " +
                                     std::to_string(*expectedBytes));
}

void checkBuffers(const GltfCheckInput& in) {
    forEachObject(in, "buffers", "buffer", [&](std::size_t i, const Json& b, const JsonPlace& place) {
        const std::int64_t byteLength = requiredInteger(place, b, "byteLength", 1, kMaxBytes);
        const auto uri = optionalString(place, b, "uri");
        if (!uri) {
            if (!in.binary) place.fail("uri", "is required in a .gltf file (only a .glb's first buffer may omit it)");
            if (i != 0) place.fail("uri", "only the first buffer of a .glb may omit uri (it is the BIN chunk)");
            if (!in.binChunkSize) place.fail("uri", "is missing and the .glb has no BIN chunk to take its place");
            if (static_cast<std::size_t>(byteLength) > *in.binChunkSize)
                place.fail("byteLength", std::to_string(byteLength) + " exceeds the GLB BIN chunk (" +
                                             std::to_string(*in.binChunkSize) + " bytes)");
        } else if (isDataUri(*uri)) {
            checkDataUri(place, *uri, byteLength);
        } else {
            checkExternalFile(in, place, *uri, byteLength);
        }
    });
}

void checkBufferViews(const GltfCheckInput& in) {
    const Json& buffers = topLevelArray(*in.root, "buffers");
    forEachObject(in, "bufferViews", "buffer view", [&](std::size_t, const Json& v, const JsonPlace& place) {
        const int buffer = requiredIndex(place, v, "buffer", buffers.size(), "buffers");
        const std::int64_t offset = optionalInteger(place, v, "byteOffset", 0, kMaxBytes).value_or(0);
        const std::int64_t length = requiredInteger(place, v, "byteLength", 1, kMaxBytes);
        const std::int64_t bufferLength = buffers[static_cast<std::size_t>(buffer)]["byteLength"].get<std::int64_t>();
        if (offset + length > bufferLength)
            place.fail("byteLength", "byteOffset + byteLength = " + std::to_string(offset + length) + " exceeds buffers[" +
                                         std::to_string(buffer) + "].byteLength (" + std::to_string(bufferLength) + ")");
        optionalInteger(place, v, "byteStride", 4, 252);
        optionalIntegerEnum(place, v, "target", {34962, 34963});
    });
}

// Byte range of `count` elements of `elementSize` bytes, `stride` apart, starting at `offset` in the view.
void checkRangeInView(const GltfCheckInput& in, const JsonPlace& place, const std::string& field, int view,
                      std::int64_t offset, std::int64_t count, std::int64_t elementSize, std::int64_t stride) {
    const Json& bv = topLevelArray(*in.root, "bufferViews")[static_cast<std::size_t>(view)];
    const std::int64_t viewLength = bv["byteLength"].get<std::int64_t>();
    const std::int64_t end = offset + stride * (count - 1) + elementSize;
    if (end > viewLength)
        place.fail(field, "the data ends at byte " + std::to_string(end) + " but bufferViews[" + std::to_string(view) +
                              "] is only " + std::to_string(viewLength) + " bytes long");
}

void checkAccessors(const GltfCheckInput& in) {
    const Json& views = topLevelArray(*in.root, "bufferViews");
    forEachObject(in, "accessors", "accessor", [&](std::size_t, const Json& a, const JsonPlace& place) {
        const auto view = optionalIndex(place, a, "bufferView", views.size(), "bufferViews");
        const auto offset = optionalInteger(place, a, "byteOffset", 0, kMaxBytes);
        if (offset && !view) place.fail("byteOffset", "is given without a bufferView");
        const auto componentTypeValue = optionalIntegerEnum(place, a, "componentType", {5120, 5121, 5122, 5123, 5125, 5126});
        if (!componentTypeValue) place.fail("componentType", "is required but missing");
        const int componentType = static_cast<int>(*componentTypeValue);
        const bool normalized = optionalBool(place, a, "normalized").value_or(false);
        if (normalized && (componentType == 5125 || componentType == 5126))
            place.fail("normalized", std::string("cannot apply to ") + componentTypeName(componentType) + " components");
        const std::int64_t count = requiredInteger(place, a, "count", 1, kMaxAccessorCount);
        const auto typeName = optionalEnum(place, a, "type", {"SCALAR", "VEC2", "VEC3", "VEC4", "MAT2", "MAT3", "MAT4"});
        if (!typeName) place.fail("type", "is required but missing");
        const ElementLayout layout = elementLayout(componentType, accessorTypeFromString(*typeName));
        const auto elementSize = static_cast<std::int64_t>(layout.elementSize);
        if (view) {
            const Json& bv = views[static_cast<std::size_t>(*view)];
            const std::int64_t stride = bv.contains("byteStride") ? bv["byteStride"].get<std::int64_t>() : elementSize;
            if (stride < elementSize)
                place.fail("bufferView", "bufferViews[" + std::to_string(*view) + "].byteStride " + std::to_string(stride) +
                                             " is smaller than the element size " + std::to_string(elementSize));
            checkRangeInView(in, place, "count", *view, offset.value_or(0), count, elementSize, stride);
        }
        const Json* sparse = optionalObject(place, a, "sparse");
        if (!sparse) return;
        const JsonPlace sp = place.nested("sparse");
        const std::int64_t sparseCount = requiredInteger(sp, *sparse, "count", 1, count);
        const Json& indices = requiredObject(sp, *sparse, "indices");
        const JsonPlace ip = sp.nested("indices");
        const int indicesView = requiredIndex(ip, indices, "bufferView", views.size(), "bufferViews");
        const std::int64_t indicesOffset = optionalInteger(ip, indices, "byteOffset", 0, kMaxBytes).value_or(0);
        const auto indexType = optionalIntegerEnum(ip, indices, "componentType", {5121, 5123, 5125});
        if (!indexType) ip.fail("componentType", "is required but missing");
        const auto indexSize = static_cast<std::int64_t>(elementLayout(static_cast<int>(*indexType), TINYGLTF_TYPE_SCALAR).elementSize);
        checkRangeInView(in, ip, "byteOffset", indicesView, indicesOffset, sparseCount, indexSize, indexSize);
        const Json& values = requiredObject(sp, *sparse, "values");
        const JsonPlace vp = sp.nested("values");
        const int valuesView = requiredIndex(vp, values, "bufferView", views.size(), "bufferViews");
        const std::int64_t valuesOffset = optionalInteger(vp, values, "byteOffset", 0, kMaxBytes).value_or(0);
        checkRangeInView(in, vp, "byteOffset", valuesView, valuesOffset, sparseCount, elementSize, elementSize);
    });
}

void checkImages(const GltfCheckInput& in) {
    const Json& views = topLevelArray(*in.root, "bufferViews");
    forEachObject(in, "images", "image", [&](std::size_t, const Json& img, const JsonPlace& place) {
        const auto uri = optionalString(place, img, "uri");
        const auto view = optionalIndex(place, img, "bufferView", views.size(), "bufferViews");
        optionalString(place, img, "mimeType");
        if (uri && view) place.fail("uri", "an image has either a uri or a bufferView, not both");
        if (!uri && !view) place.fail("uri", "an image needs a uri or a bufferView");
        if (uri && isDataUri(*uri)) checkDataUri(place, *uri, std::nullopt);
        else if (uri) checkExternalFile(in, place, *uri, std::nullopt);
    });
}

void checkSamplersAndTextures(const GltfCheckInput& in) {
    forEachObject(in, "samplers", "sampler", [&](std::size_t, const Json& s, const JsonPlace& place) {
        optionalIntegerEnum(place, s, "magFilter", {9728, 9729});
        optionalIntegerEnum(place, s, "minFilter", {9728, 9729, 9984, 9985, 9986, 9987});
        optionalIntegerEnum(place, s, "wrapS", {33071, 33648, 10497});
        optionalIntegerEnum(place, s, "wrapT", {33071, 33648, 10497});
    });
    const std::size_t samplers = topLevelArray(*in.root, "samplers").size();
    const std::size_t images = topLevelArray(*in.root, "images").size();
    forEachObject(in, "textures", "texture", [&](std::size_t, const Json& t, const JsonPlace& place) {
        optionalIndex(place, t, "sampler", samplers, "samplers");
        optionalIndex(place, t, "source", images, "images");
        // EXT_texture_webp names its image in the extension (tinygltf-decodable through OIIO).
        if (const Json* ext = optionalObject(place, t, "extensions"))
            if (const Json* webp = optionalObject(place.nested("extensions"), *ext, "EXT_texture_webp"))
                optionalIndex(place.nested("extensions").nested("EXT_texture_webp"), *webp, "source", images, "images");
    });
}

// KHR_texture_transform on a textureInfo: offset, rotation, scale and an optional texCoord override.
std::optional<std::int64_t> checkTextureTransform(const JsonPlace& place, const Json& info) {
    const Json* ext = optionalObject(place, info, "extensions");
    if (!ext) return std::nullopt;
    const Json* transform = optionalObject(place.nested("extensions"), *ext, "KHR_texture_transform");
    if (!transform) return std::nullopt;
    const JsonPlace t = place.nested("extensions").nested("KHR_texture_transform");
    optionalNumberArray(t, *transform, "offset", 2, -kHuge, kHuge);
    optionalNumber(t, *transform, "rotation", -kHuge, kHuge);
    optionalNumberArray(t, *transform, "scale", 2, -kHuge, kHuge);
    return optionalInteger(t, *transform, "texCoord", 0, 1 << 20);
}

// A textureInfo object: {"index": texture, "texCoord": n, "extensions": {"KHR_texture_transform": ...}}.
// Returns the TEXCOORD set it reads (the transform's texCoord wins), or -1 when absent. `drawn`
// textures must read TEXCOORD_0 or TEXCOORD_1; the others are checked, not drawn.
int checkTextureInfo(const GltfCheckInput& in, const JsonPlace& place, const Json& owner, const char* key, bool drawn) {
    const Json* info = optionalObject(place, owner, key);
    if (!info) return -1;
    const JsonPlace p = place.nested(key);
    requiredIndex(p, *info, "index", topLevelArray(*in.root, "textures").size(), "textures");
    int set = static_cast<int>(optionalInteger(p, *info, "texCoord", 0, 1 << 20).value_or(0));
    if (const auto overridden = checkTextureTransform(p, *info)) set = static_cast<int>(*overridden);
    if (drawn && set > 1)
        p.fail("texCoord", "TEXCOORD_" + std::to_string(set) + " is not supported (Nimbus reads TEXCOORD_0 and TEXCOORD_1)");
    return set;
}

void checkMaterials(const GltfCheckInput& in) {
    forEachObject(in, "materials", "material", [&](std::size_t, const Json& m, const JsonPlace& place) {
        if (const Json* pbr = optionalObject(place, m, "pbrMetallicRoughness")) {
            const JsonPlace p = place.nested("pbrMetallicRoughness");
            optionalNumberArray(p, *pbr, "baseColorFactor", 4, 0.0, 1.0);
            optionalNumber(p, *pbr, "metallicFactor", 0.0, 1.0);
            optionalNumber(p, *pbr, "roughnessFactor", 0.0, 1.0);
            checkTextureInfo(in, p, *pbr, "baseColorTexture", true);
            checkTextureInfo(in, p, *pbr, "metallicRoughnessTexture", true);
        }
        checkTextureInfo(in, place, m, "normalTexture", false);
        checkTextureInfo(in, place, m, "occlusionTexture", false);
        checkTextureInfo(in, place, m, "emissiveTexture", true);
        optionalNumberArray(place, m, "emissiveFactor", 3, 0.0, kHuge);
        const auto mode = optionalEnum(place, m, "alphaMode", {"OPAQUE", "MASK", "BLEND"});
        // Transparent meshes would have to be sorted and composed with the media; until they are,
        // a BLEND material is refused rather than drawn opaque (docs/scene-format.md §4.1).
        if (mode == "BLEND")
            place.fail("alphaMode", "BLEND is not supported (transparent meshes are not composed with the media yet); "
                                    "use OPAQUE or MASK");
        optionalNumber(place, m, "alphaCutoff", 0.0, kHuge);
        optionalBool(place, m, "doubleSided");
    });
}

const Json& accessorJson(const GltfCheckInput& in, int index) {
    return topLevelArray(*in.root, "accessors")[static_cast<std::size_t>(index)];
}

// The accessor behind an attribute must have one of the allowed layouts.
struct AllowedLayout {
    const char* type;
    int componentType;
    bool normalized;
};

void checkAttributeLayout(const GltfCheckInput& in, const JsonPlace& place, const std::string& field, int accessor,
                          std::initializer_list<AllowedLayout> allowed) {
    const Json& a = accessorJson(in, accessor);
    const std::string type = a["type"].get<std::string>();
    const int componentType = a["componentType"].get<int>();
    const bool normalized = a.value("normalized", false);
    std::string expected;
    for (const AllowedLayout& l : allowed) {
        if (type == l.type && componentType == l.componentType && normalized == l.normalized) return;
        expected += std::string(expected.empty() ? "" : " or ") + l.type + " " + componentTypeName(l.componentType) +
                    (l.normalized ? " normalized" : "");
    }
    place.fail(field, "accessors[" + std::to_string(accessor) + "] is " + type + " " + componentTypeName(componentType) +
                          (normalized ? " normalized" : "") + ", expected " + expected);
}

void checkPrimitive(const GltfCheckInput& in, const JsonPlace& place, const Json& prim) {
    const std::size_t accessors = topLevelArray(*in.root, "accessors").size();
    const Json& materials = topLevelArray(*in.root, "materials");
    const Json& attributes = requiredObject(place, prim, "attributes");
    const JsonPlace ap = place.nested("attributes");
    std::int64_t vertexCount = -1;
    std::string firstAttribute;
    for (auto it = attributes.begin(); it != attributes.end(); ++it) {
        checkIndexValue(ap, it.key(), it.value(), accessors, "accessors");
        const int accessor = it.value().get<int>();
        const std::int64_t count = accessorJson(in, accessor)["count"].get<std::int64_t>();
        if (vertexCount < 0) {
            vertexCount = count;
            firstAttribute = it.key();
        } else if (count != vertexCount) {
            ap.fail(it.key(), "count " + std::to_string(count) + " differs from " + firstAttribute + "'s " +
                                  std::to_string(vertexCount) + " (all attributes of a primitive have one count)");
        }
        const std::string& name = it.key();
        if (name == "POSITION" || name == "NORMAL") {
            checkAttributeLayout(in, ap, name, accessor, {{"VEC3", 5126, false}});
        } else if (name == "TEXCOORD_0" || name == "TEXCOORD_1") {
            checkAttributeLayout(in, ap, name, accessor, {{"VEC2", 5126, false}, {"VEC2", 5121, true}, {"VEC2", 5123, true}});
        } else if (name == "COLOR_0") {
            checkAttributeLayout(in, ap, name, accessor,
                                 {{"VEC3", 5126, false}, {"VEC4", 5126, false}, {"VEC3", 5121, true}, {"VEC4", 5121, true},
                                  {"VEC3", 5123, true}, {"VEC4", 5123, true}});
        }
    }
    const auto indices = optionalIndex(place, prim, "indices", accessors, "accessors");
    if (indices) {
        checkAttributeLayout(in, place, "indices", *indices, {{"SCALAR", 5121, false}, {"SCALAR", 5123, false}, {"SCALAR", 5125, false}});
        if (!accessorJson(in, *indices).contains("bufferView"))  // tinygltf cannot load it (and all-zero indices make no triangles)
            place.fail("indices", "accessors[" + std::to_string(*indices) + "] has no bufferView");
    }
    const auto material = optionalIndex(place, prim, "material", materials.size(), "materials");
    const std::int64_t mode = optionalIntegerEnum(place, prim, "mode", {0, 1, 2, 3, 4, 5, 6}).value_or(4);
    if (const Json* targets = optionalArray(place, prim, "targets")) {
        for (std::size_t t = 0; t < targets->size(); ++t) {
            const JsonPlace tp = place.nested("targets[" + std::to_string(t) + "]");
            if (!(*targets)[t].is_object()) place.fail("targets[" + std::to_string(t) + "]", "must be a JSON object");
            for (auto it = (*targets)[t].begin(); it != (*targets)[t].end(); ++it)
                checkIndexValue(tp, it.key(), it.value(), accessors, "accessors");
        }
    }
    if (mode == 4 && attributes.contains("POSITION")) {
        const std::int64_t n = indices ? accessorJson(in, *indices)["count"].get<std::int64_t>() : vertexCount;
        if (n % 3 != 0)
            place.fail(indices ? "indices" : "attributes.POSITION",
                       "count " + std::to_string(n) + " is not a multiple of 3 (mode TRIANGLES)");
    }
    // A material sampling TEXCOORD_n needs the primitive to have it.
    if (material && attributes.contains("POSITION")) {
        const Json& m = materials[static_cast<std::size_t>(*material)];
        const std::string name = describeObject("material", "materials", static_cast<std::size_t>(*material), m);
        const JsonPlace mp{place.file, name, ""};
        auto need = [&](const Json& owner, const char* key, const std::string& field) {
            const int set = checkTextureInfo(in, mp, owner, key, false);
            const std::string needed = "TEXCOORD_" + std::to_string(set);
            if (set >= 0 && !attributes.contains(needed))
                ap.fail(needed, "missing, but " + name + " samples its " + field + " with it");
        };
        if (m.contains("pbrMetallicRoughness")) {
            need(m["pbrMetallicRoughness"], "baseColorTexture", "baseColorTexture");
            need(m["pbrMetallicRoughness"], "metallicRoughnessTexture", "metallicRoughnessTexture");
        }
        need(m, "emissiveTexture", "emissiveTexture");
    }
}

void checkMeshes(const GltfCheckInput& in) {
    forEachObject(in, "meshes", "mesh", [&](std::size_t, const Json& mesh, const JsonPlace& place) {
        const Json* prims = optionalArray(place, mesh, "primitives");
        if (!prims || prims->empty()) place.fail("primitives", "a mesh needs at least one primitive");
        for (std::size_t p = 0; p < prims->size(); ++p) {
            const JsonPlace pp{place.file, place.object, "primitives[" + std::to_string(p) + "]."};
            if (!(*prims)[p].is_object()) place.fail("primitives[" + std::to_string(p) + "]", "must be a JSON object");
            checkPrimitive(in, pp, (*prims)[p]);
        }
        optionalArray(place, mesh, "weights");
    });
}

void checkSkins(const GltfCheckInput& in) {
    const std::size_t nodes = topLevelArray(*in.root, "nodes").size();
    const std::size_t accessors = topLevelArray(*in.root, "accessors").size();
    forEachObject(in, "skins", "skin", [&](std::size_t, const Json& s, const JsonPlace& place) {
        optionalIndex(place, s, "inverseBindMatrices", accessors, "accessors");
        optionalIndex(place, s, "skeleton", nodes, "nodes");
        const Json* joints = optionalArray(place, s, "joints");
        if (!joints) place.fail("joints", "is required but missing");
        for (std::size_t j = 0; j < joints->size(); ++j)
            checkIndexValue(place, "joints[" + std::to_string(j) + "]", (*joints)[j], nodes, "nodes");
    });
}

}  // namespace

void checkGltfData(const GltfCheckInput& in) {
    checkBuffers(in);
    checkBufferViews(in);
    checkAccessors(in);
    checkImages(in);
    checkSamplersAndTextures(in);
    checkMaterials(in);
    checkMeshes(in);
    checkSkins(in);
}

}  // namespace nimbus::assets
