#include "gltf_mesh_builder.h"

#include <cmath>
#include <numeric>

#include "gltf_accessor.h"
#include "json_fields.h"
#include "nimbus/base/error.h"
#include "nimbus/base/log.h"

namespace nimbus::assets {
namespace {

const char* modeName(int mode) {
    switch (mode) {
        case TINYGLTF_MODE_POINTS: return "POINTS";
        case TINYGLTF_MODE_LINE: return "LINES";
        case TINYGLTF_MODE_LINE_LOOP: return "LINE_LOOP";
        case TINYGLTF_MODE_LINE_STRIP: return "LINE_STRIP";
        case TINYGLTF_MODE_TRIANGLE_STRIP: return "TRIANGLE_STRIP";
        case TINYGLTF_MODE_TRIANGLE_FAN: return "TRIANGLE_FAN";
        default: return "TRIANGLES";
    }
}

int attributeAccessor(const tinygltf::Primitive& prim, const char* name) {
    const auto it = prim.attributes.find(name);
    return it == prim.attributes.end() ? -1 : it->second;
}

template <class Vec, int N>
std::vector<Vec> readVectors(const tinygltf::Model& model, int accessor, const std::string& file, const JsonPlace& place,
                             const std::string& field) {
    const std::vector<float> flat = readAccessorFloats(model, accessor, file);
    std::vector<Vec> out(flat.size() / N);
    for (std::size_t i = 0; i < out.size(); ++i) {
        for (int c = 0; c < N; ++c) {
            const float v = flat[i * N + static_cast<std::size_t>(c)];
            if (!std::isfinite(v))
                place.fail(field, "vertex " + std::to_string(i) + " is not finite (" + describeAccessor(model, accessor) + ")");
            out[i][c] = v;
        }
    }
    return out;
}

// glTF 2.0 §3.7.2.1: strips and fans as triangle lists with the winding of their first triangle.
std::vector<std::uint32_t> toTriangleList(const std::vector<std::uint32_t>& v, int mode) {
    if (mode == TINYGLTF_MODE_TRIANGLES) return v;
    std::vector<std::uint32_t> out;
    if (v.size() < 3) return out;
    out.reserve((v.size() - 2) * 3);
    for (std::size_t i = 0; i + 2 < v.size(); ++i) {
        if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
            const std::size_t odd = i % 2;
            out.insert(out.end(), {v[i], v[i + 1 + odd], v[i + 2 - odd]});
        } else {  // fan
            out.insert(out.end(), {v[i + 1], v[i + 2], v[0]});
        }
    }
    return out;
}

// Flat shading needs one normal per triangle corner: every triangle gets its own three vertices.
void unweldWithFlatNormals(Primitive& p) {
    const std::size_t corners = p.indices.size();
    std::vector<glm::vec3> positions(corners), normals(corners);
    std::vector<glm::vec2> uv0(p.texcoords0.empty() ? 0 : corners), uv1(p.texcoords1.empty() ? 0 : corners);
    std::vector<glm::vec4> colors(p.colors0.empty() ? 0 : corners);
    for (std::size_t t = 0; t + 2 < corners; t += 3) {
        const glm::vec3 n = triangleNormal(p.positions[p.indices[t]], p.positions[p.indices[t + 1]], p.positions[p.indices[t + 2]]);
        for (std::size_t k = t; k < t + 3; ++k) {
            positions[k] = p.positions[p.indices[k]];
            normals[k] = n;
            if (!uv0.empty()) uv0[k] = p.texcoords0[p.indices[k]];
            if (!uv1.empty()) uv1[k] = p.texcoords1[p.indices[k]];
            if (!colors.empty()) colors[k] = p.colors0[p.indices[k]];
        }
    }
    p.positions = std::move(positions);
    p.normals = std::move(normals);
    p.texcoords0 = std::move(uv0);
    p.texcoords1 = std::move(uv1);
    p.colors0 = std::move(colors);
    std::iota(p.indices.begin(), p.indices.end(), 0u);
}

// Builds one primitive; false when it is dropped (not triangles, no positions, no triangles left).
bool buildPrimitive(const tinygltf::Model& model, const tinygltf::Primitive& prim, const std::string& file,
                    const JsonPlace& place, const std::string& where, Primitive& out) {
    const int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
    if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP && mode != TINYGLTF_MODE_TRIANGLE_FAN) {
        log::warn(file + ": " + where + ": mode " + modeName(mode) + " is not drawn (Nimbus draws triangles only); primitive dropped");
        return false;
    }
    const int positionAccessor = attributeAccessor(prim, "POSITION");
    if (positionAccessor < 0) {
        log::warn(file + ": " + where + ": no POSITION attribute; primitive dropped (glTF: skip it)");
        return false;
    }
    out.positions = readVectors<glm::vec3, 3>(model, positionAccessor, file, place, "attributes.POSITION");
    const std::size_t vertexCount = out.positions.size();

    if (const int a = attributeAccessor(prim, "NORMAL"); a >= 0) {
        out.normals = readVectors<glm::vec3, 3>(model, a, file, place, "attributes.NORMAL");
        for (std::size_t i = 0; i < out.normals.size(); ++i) {
            const float length = glm::length(out.normals[i]);
            if (!(length > 1e-6f))
                place.fail("attributes.NORMAL", "vertex " + std::to_string(i) + " has a zero-length normal (glTF normals are unit vectors)");
            out.normals[i] /= length;
        }
    }
    if (const int a = attributeAccessor(prim, "TEXCOORD_0"); a >= 0)
        out.texcoords0 = readVectors<glm::vec2, 2>(model, a, file, place, "attributes.TEXCOORD_0");
    if (const int a = attributeAccessor(prim, "TEXCOORD_1"); a >= 0)
        out.texcoords1 = readVectors<glm::vec2, 2>(model, a, file, place, "attributes.TEXCOORD_1");
    if (const int a = attributeAccessor(prim, "COLOR_0"); a >= 0) {
        // VEC3 or VEC4 (checked): RGB gets alpha 1. Values are linear, as glTF stores them.
        if (model.accessors[static_cast<std::size_t>(a)].type == TINYGLTF_TYPE_VEC3) {
            for (const glm::vec3& c : readVectors<glm::vec3, 3>(model, a, file, place, "attributes.COLOR_0")) out.colors0.emplace_back(c, 1.0f);
        } else {
            out.colors0 = readVectors<glm::vec4, 4>(model, a, file, place, "attributes.COLOR_0");
        }
    }

    std::vector<std::uint32_t> indices;
    if (prim.indices >= 0) {
        indices = readAccessorIndices(model, prim.indices, file);
        for (std::size_t i = 0; i < indices.size(); ++i)
            if (indices[i] >= vertexCount)
                place.fail("indices", "value " + std::to_string(indices[i]) + " at position " + std::to_string(i) +
                                          " is not below the vertex count " + std::to_string(vertexCount));
    } else {
        indices.assign(vertexCount, 0u);
        std::iota(indices.begin(), indices.end(), 0u);
    }
    if (mode == TINYGLTF_MODE_TRIANGLES && indices.size() % 3 != 0)
        place.fail(prim.indices >= 0 ? "indices" : "attributes.POSITION",
                   "count " + std::to_string(indices.size()) + " is not a multiple of 3 (mode TRIANGLES)");
    out.indices = toTriangleList(indices, mode);
    if (out.indices.empty()) {
        log::warn(file + ": " + where + ": " + modeName(mode) + " with fewer than 3 vertices has no triangles; primitive dropped");
        return false;
    }
    if (out.normals.empty()) unweldWithFlatNormals(out);

    out.material = prim.material;
    out.boundsMin = out.boundsMax = out.positions[out.indices[0]];
    for (const std::uint32_t i : out.indices) {
        out.boundsMin = glm::min(out.boundsMin, out.positions[i]);
        out.boundsMax = glm::max(out.boundsMax, out.positions[i]);
    }
    return true;
}

}  // namespace

glm::vec3 triangleNormal(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    const glm::dvec3 da(a), db(b), dc(c);
    const glm::dvec3 n = glm::cross(db - da, dc - da);
    const double length = glm::length(n);
    if (length > 0.0 && std::isfinite(length)) return glm::vec3(n / length);
    // Degenerate: any unit vector perpendicular to the longest edge keeps shading finite.
    glm::dvec3 edge = db - da;
    for (const glm::dvec3& e : {dc - db, da - dc})
        if (glm::length(e) > glm::length(edge)) edge = e;
    const double edgeLength = glm::length(edge);
    if (!(edgeLength > 0.0) || !std::isfinite(edgeLength)) return {0.0f, 1.0f, 0.0f};
    const glm::dvec3 d = edge / edgeLength;
    // Cross with the axis least aligned with the edge: never (anti)parallel.
    const glm::dvec3 ad = glm::abs(d);
    const glm::dvec3 axis = ad.x <= ad.y && ad.x <= ad.z ? glm::dvec3(1, 0, 0) : ad.y <= ad.z ? glm::dvec3(0, 1, 0) : glm::dvec3(0, 0, 1);
    return glm::vec3(glm::normalize(glm::cross(d, axis)));
}

std::vector<Mesh> buildMeshes(const tinygltf::Model& model, const nlohmann::json& root, const std::string& file) {
    std::vector<Mesh> meshes(model.meshes.size());
    for (std::size_t m = 0; m < model.meshes.size(); ++m) {
        const tinygltf::Mesh& src = model.meshes[m];
        const std::string object = describeObject("mesh", "meshes", m, root["meshes"][m]);
        meshes[m].name = src.name;
        for (std::size_t p = 0; p < src.primitives.size(); ++p) {
            const std::string prefix = "primitives[" + std::to_string(p) + "].";
            const JsonPlace place{&file, object, prefix};
            Primitive prim;
            if (buildPrimitive(model, src.primitives[p], file, place, object + ": " + prefix.substr(0, prefix.size() - 1), prim))
                meshes[m].primitives.push_back(std::move(prim));
        }
    }
    return meshes;
}

}  // namespace nimbus::assets
