#pragma once
// A glTF 2.0 file read with tinygltf into plain data: nodes (rest pose), triangle meshes with
// positions, normals and indices, baseColorFactor materials, cameras, KHR_lights_punctual lights,
// TRS animation channels, and the NIMBUS_participating_media objects kept as raw JSON for the
// media module.
//
// Does not: read textures, skins, morph targets, strips/fans, sparse or normalized accessors, or
// validate the extension's contents (the media plugin does that).
#include <cstdint>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>

#include "nimbus/gpu/light_views.h"

namespace tinygltf {
class Model;
}

namespace mini {

// What a user can fix: a missing or malformed file (main exits 1 with this one line).
class SceneError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

inline constexpr const char* kMediaExtension = "NIMBUS_participating_media";

struct Primitive {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;       // unit; flat per triangle when the file has none
    std::vector<std::uint32_t> indices;   // triangle list
    int material = -1;                    // −1: glTF default material (white, single-sided)
    glm::vec3 boundsMin{0.0f}, boundsMax{0.0f};
};

struct Mesh {
    std::string name;
    std::vector<Primitive> primitives;
};

// glTF metallic-roughness factors (glTF's defaults); textures are not read.
struct Material {
    glm::vec4 baseColorFactor{1.0f};  // linear
    float metallicFactor = 1.0f;
    float roughnessFactor = 1.0f;
    glm::vec3 emissiveFactor{0.0f};
    bool doubleSided = false;
};

struct Camera {
    bool orthographic = false;
    double yfov = 0.8;    // radians
    double ymag = 1.0;    // orthographic half height
    double znear = 0.05;
    double zfar = 0.0;    // 0: infinite (perspective)
};

struct Light {
    std::string name;
    nimbus::gpu::LightKind kind = nimbus::gpu::LightKind::Directional;
    glm::vec3 color{1.0f};
    float intensity = 1.0f;  // lux (directional) or candela
    double range = 0.0;      // 0: infinite
    double innerConeAngle = 0.0;
    double outerConeAngle = 0.7853981633974483;
};

struct Pose {
    glm::dvec3 translation{0.0};
    glm::dquat rotation{1.0, 0.0, 0.0, 0.0};
    glm::dvec3 scale{1.0};
};

struct Node {
    std::string name;
    std::vector<int> children;
    int parent = -1;
    bool hasMatrix = false;   // then `matrix` is the local transform and the node is not animated
    glm::dmat4 matrix{1.0};
    Pose pose;
    int mesh = -1, camera = -1, light = -1;
    nlohmann::json media;     // the node's NIMBUS_participating_media object as written; null when absent
};

enum class AnimationPath { Translation, Rotation, Scale };
enum class Interpolation { Linear, Step, CubicSpline };

struct Channel {
    int node = -1;
    AnimationPath path = AnimationPath::Translation;
    Interpolation interpolation = Interpolation::Linear;
    std::vector<float> times;       // increasing
    std::vector<glm::vec4> values;  // xyz, or quaternion xyzw; cubic spline: in-tangent, value, out-tangent per key
};

struct Environment {
    glm::vec3 background{0.0f};  // radiance of rays that hit nothing
    glm::vec3 ambient{0.0f};     // isotropic sky radiance
};

struct Scene {
    std::filesystem::path path;
    std::vector<Node> nodes;
    std::vector<int> roots;  // of the displayed scene
    std::vector<bool> shown; // per node: reachable from `roots`
    std::vector<Mesh> meshes;
    std::vector<Material> materials;
    std::vector<Camera> cameras;
    std::vector<Light> lights;
    std::vector<Channel> channels;  // of every animation: all play together
    Environment environment;
    nlohmann::json mediaRoot;  // the root NIMBUS_participating_media object; null when absent
    // The parsed file, kept for the media module's reads of particle accessors (gltf_data.h).
    std::shared_ptr<const tinygltf::Model> model;
};

// Throws SceneError naming the file and the object at fault.
Scene loadScene(const std::filesystem::path& file);

}  // namespace mini
