#include "gltf_data.h"

#include <cmath>
#include <cstring>
#include <numeric>

namespace mini::gltf {
namespace {

[[noreturn]] void fail(const std::string& where, const std::string& problem) { throw SceneError(where + ": " + problem); }

// The bytes of element i of an accessor, bounds-checked against its buffer.
struct AccessorBytes {
    const unsigned char* first = nullptr;
    std::size_t stride = 0;
    std::size_t count = 0;
};

AccessorBytes accessorBytes(const tinygltf::Model& model, int index, std::size_t elementSize, const std::string& where) {
    if (index < 0 || static_cast<std::size_t>(index) >= model.accessors.size()) fail(where, "accessor " + std::to_string(index) + " does not exist");
    const tinygltf::Accessor& a = model.accessors[static_cast<std::size_t>(index)];
    if (a.sparse.isSparse) fail(where, "sparse accessors are not read by mini_host");
    if (a.bufferView < 0 || static_cast<std::size_t>(a.bufferView) >= model.bufferViews.size()) fail(where, "accessor has no buffer view");
    const tinygltf::BufferView& view = model.bufferViews[static_cast<std::size_t>(a.bufferView)];
    const tinygltf::Buffer& buffer = model.buffers.at(static_cast<std::size_t>(view.buffer));
    AccessorBytes out;
    out.stride = view.byteStride > 0 ? view.byteStride : elementSize;
    out.count = a.count;
    const std::size_t start = view.byteOffset + a.byteOffset;
    const std::size_t end = a.count == 0 ? start : start + (a.count - 1) * out.stride + elementSize;
    if (end > view.byteOffset + view.byteLength || end > buffer.data.size()) fail(where, "accessor runs past its buffer");
    out.first = buffer.data.data() + start;
    return out;
}

// glTF §3.7.2.1 per-triangle normal, in double so thin triangles keep a usable direction.
glm::vec3 triangleNormal(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    const glm::dvec3 n = glm::cross(glm::dvec3(b) - glm::dvec3(a), glm::dvec3(c) - glm::dvec3(a));
    const double length = glm::length(n);
    return length > 0.0 && std::isfinite(length) ? glm::vec3(n / length) : glm::vec3(0.0f, 1.0f, 0.0f);
}

// Flat shading needs a normal per triangle corner, so every triangle gets its own vertices.
void flatNormals(Primitive& p) {
    std::vector<glm::vec3> positions(p.indices.size()), normals(p.indices.size());
    for (std::size_t t = 0; t + 2 < p.indices.size(); t += 3) {
        const glm::vec3 n = triangleNormal(p.positions[p.indices[t]], p.positions[p.indices[t + 1]], p.positions[p.indices[t + 2]]);
        for (std::size_t k = t; k < t + 3; ++k) {
            positions[k] = p.positions[p.indices[k]];
            normals[k] = n;
        }
    }
    p.positions = std::move(positions);
    p.normals = std::move(normals);
    std::iota(p.indices.begin(), p.indices.end(), 0u);
}

std::vector<glm::vec3> readVec3s(const tinygltf::Model& model, int accessor, const std::string& where) {
    const std::vector<float> flat = readFloats(model, accessor, 3, where);
    std::vector<glm::vec3> out(flat.size() / 3);
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = {flat[3 * i], flat[3 * i + 1], flat[3 * i + 2]};
    return out;
}

// One primitive; false when it is not drawn (not triangles, or no POSITION).
bool readPrimitive(const tinygltf::Model& model, const tinygltf::Primitive& src, const std::string& where, Primitive& out) {
    if (src.mode >= 0 && src.mode != TINYGLTF_MODE_TRIANGLES) return false;
    const auto position = src.attributes.find("POSITION");
    if (position == src.attributes.end()) return false;
    out.positions = readVec3s(model, position->second, where + ".POSITION");
    if (const auto normal = src.attributes.find("NORMAL"); normal != src.attributes.end()) {
        out.normals = readVec3s(model, normal->second, where + ".NORMAL");
        if (out.normals.size() != out.positions.size()) fail(where + ".NORMAL", "count differs from POSITION");
        for (glm::vec3& n : out.normals) {
            const float length = glm::length(n);
            if (!(length > 1e-6f)) fail(where + ".NORMAL", "zero-length normal");
            n /= length;  // as Nimbus does, so both hosts shade with the same float normals
        }
    }
    if (src.indices >= 0) {
        out.indices = readIndices(model, src.indices, where + ".indices");
    } else {
        out.indices.resize(out.positions.size());
        std::iota(out.indices.begin(), out.indices.end(), 0u);
    }
    if (out.indices.size() % 3 != 0 || out.indices.empty()) fail(where, "not a whole number of triangles");
    for (const std::uint32_t i : out.indices)
        if (i >= out.positions.size()) fail(where + ".indices", "index " + std::to_string(i) + " is past the last vertex");
    if (out.normals.empty()) flatNormals(out);
    out.material = src.material;
    out.boundsMin = out.boundsMax = out.positions[out.indices[0]];
    for (const std::uint32_t i : out.indices) {
        out.boundsMin = glm::min(out.boundsMin, out.positions[i]);
        out.boundsMax = glm::max(out.boundsMax, out.positions[i]);
    }
    return true;
}

AnimationPath animationPath(const std::string& path) {
    if (path == "rotation") return AnimationPath::Rotation;
    if (path == "scale") return AnimationPath::Scale;
    return AnimationPath::Translation;
}

Interpolation interpolation(const std::string& name) {
    if (name == "STEP") return Interpolation::Step;
    if (name == "CUBICSPLINE") return Interpolation::CubicSpline;
    return Interpolation::Linear;
}

}  // namespace

std::vector<float> readFloats(const tinygltf::Model& model, int accessor, int components, const std::string& where) {
    const AccessorBytes bytes = accessorBytes(model, accessor, sizeof(float) * static_cast<std::size_t>(components), where);
    const tinygltf::Accessor& a = model.accessors[static_cast<std::size_t>(accessor)];
    if (a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT || tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(a.type)) != components)
        fail(where, "expected a FLOAT accessor with " + std::to_string(components) + " components");
    std::vector<float> out(bytes.count * static_cast<std::size_t>(components));
    for (std::size_t i = 0; i < bytes.count; ++i)
        std::memcpy(&out[i * static_cast<std::size_t>(components)], bytes.first + i * bytes.stride, sizeof(float) * static_cast<std::size_t>(components));
    for (const float v : out)
        if (!std::isfinite(v)) fail(where, "value is not finite");
    return out;
}

std::size_t accessorCount(const tinygltf::Model& model, int accessor, int components, const std::string& where) {
    const AccessorBytes bytes = accessorBytes(model, accessor, sizeof(float) * static_cast<std::size_t>(components), where);
    return bytes.count;
}

std::vector<std::uint32_t> readIndices(const tinygltf::Model& model, int accessor, const std::string& where) {
    if (accessor < 0 || static_cast<std::size_t>(accessor) >= model.accessors.size()) fail(where, "accessor does not exist");
    const int type = model.accessors[static_cast<std::size_t>(accessor)].componentType;
    const std::size_t size = type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ? 1 : type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ? 2 : 4;
    if (size == 4 && type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT) fail(where, "indices must be unsigned integers");
    const AccessorBytes bytes = accessorBytes(model, accessor, size, where);
    std::vector<std::uint32_t> out(bytes.count);
    for (std::size_t i = 0; i < bytes.count; ++i) {
        const unsigned char* p = bytes.first + i * bytes.stride;
        if (size == 1) out[i] = *p;
        else if (size == 2) { std::uint16_t v; std::memcpy(&v, p, 2); out[i] = v; }
        else std::memcpy(&out[i], p, 4);
    }
    return out;
}

std::vector<Mesh> readMeshes(const tinygltf::Model& model, const std::string& file) {
    std::vector<Mesh> meshes(model.meshes.size());
    for (std::size_t m = 0; m < model.meshes.size(); ++m) {
        meshes[m].name = model.meshes[m].name;
        for (std::size_t p = 0; p < model.meshes[m].primitives.size(); ++p) {
            const std::string where = file + ": meshes[" + std::to_string(m) + "].primitives[" + std::to_string(p) + "]";
            Primitive primitive;
            if (readPrimitive(model, model.meshes[m].primitives[p], where, primitive)) meshes[m].primitives.push_back(std::move(primitive));
        }
    }
    return meshes;
}

std::vector<Channel> readChannels(const tinygltf::Model& model, const std::string& file) {
    std::vector<Channel> channels;
    for (std::size_t a = 0; a < model.animations.size(); ++a) {
        const tinygltf::Animation& animation = model.animations[a];
        for (std::size_t c = 0; c < animation.channels.size(); ++c) {
            const tinygltf::AnimationChannel& src = animation.channels[c];
            if (src.target_node < 0 || src.target_path == "weights") continue;  // glTF: no target node, ignore
            const std::string where = file + ": animations[" + std::to_string(a) + "].channels[" + std::to_string(c) + "]";
            const tinygltf::AnimationSampler& sampler = animation.samplers.at(static_cast<std::size_t>(src.sampler));
            Channel channel;
            channel.node = src.target_node;
            channel.path = animationPath(src.target_path);
            channel.interpolation = interpolation(sampler.interpolation);
            channel.times = readFloats(model, sampler.input, 1, where + ".input");
            const int components = channel.path == AnimationPath::Rotation ? 4 : 3;
            const std::vector<float> flat = readFloats(model, sampler.output, components, where + ".output");
            const std::size_t perKey = channel.interpolation == Interpolation::CubicSpline ? 3 : 1;
            if (flat.size() / static_cast<std::size_t>(components) != perKey * channel.times.size()) fail(where, "output count does not match input");
            for (std::size_t i = 0; i < flat.size(); i += static_cast<std::size_t>(components))
                channel.values.emplace_back(flat[i], flat[i + 1], flat[i + 2], components == 4 ? flat[i + 3] : 0.0f);
            channels.push_back(std::move(channel));
        }
    }
    return channels;
}

}  // namespace mini::gltf
