#pragma once
// A loaded glTF 2.0 scene: the standard parts Nimbus draws (meshes, materials, textures, cameras,
// KHR_lights_punctual lights, node animation) plus the raw extension objects that plugins parse.
// Everything is validated at load time: a Scene that exists is complete and in range.
//
// Materials are glTF's metallic-roughness model (docs/scene-format.md §4.1 says how it is shaded).
// Does not: keep skins, morph targets, normal or occlusion textures, or material extensions other
// than KHR_texture_transform.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>

namespace nimbus::assets {

// The name of our glTF extension (docs/design.md §4), on the root and on nodes.
inline constexpr const char* kMediaExtension = "NIMBUS_participating_media";

struct Image {
    std::string name;
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba8;  // row 0 is the top row; values as stored (sRGB-encoded for baseColor),
                                      // straight alpha; grey / RGB files are expanded, alpha 255 when absent
};

enum class Wrap { Repeat, ClampToEdge, MirroredRepeat };
enum class Filter { Nearest, Linear };

struct Texture {
    int image = -1;
    Wrap wrapS = Wrap::Repeat;
    Wrap wrapT = Wrap::Repeat;
    Filter magFilter = Filter::Linear;
    Filter minFilter = Filter::Linear;
    bool mipmaps = true;  // minFilter asked for a mipmapped mode (or left it to us)
};

// A textureInfo: which texture, which TEXCOORD_n set, and KHR_texture_transform as one affine map
// uv' = (dot(row0, (u, v, 1)), dot(row1, (u, v, 1))) = offset + rotation · scale · uv.
struct TextureRef {
    int texture = -1;  // index into Scene::textures, -1 for none
    int texCoord = 0;  // the TEXCOORD_n set it reads (KHR_texture_transform's texCoord wins)
    glm::vec3 row0{1.0f, 0.0f, 0.0f};
    glm::vec3 row1{0.0f, 1.0f, 0.0f};

    bool present() const { return texture >= 0; }
    glm::dvec2 transform(const glm::dvec2& uv) const {
        return {row0.x * uv.x + row0.y * uv.y + row0.z, row1.x * uv.x + row1.y * uv.y + row1.z};
    }
};

enum class AlphaMode { Opaque, Mask, Blend };

// glTF 2.0's metallic-roughness material. The defaults are glTF's, so a Material{} is the glTF
// default material: white, metallic 1, roughness 1, single-sided.
struct Material {
    std::string name;
    glm::vec4 baseColorFactor{1.0f};  // linear
    TextureRef baseColorTexture;      // sRGB-encoded rgb, linear alpha
    float metallicFactor = 1.0f;
    float roughnessFactor = 1.0f;
    TextureRef metallicRoughnessTexture;  // linear: roughness in green, metalness in blue
    glm::vec3 emissiveFactor{0.0f};       // linear radiance
    TextureRef emissiveTexture;           // sRGB-encoded
    AlphaMode alphaMode = AlphaMode::Opaque;  // Blend is refused at load (docs/scene-format.md §4.1)
    float alphaCutoff = 0.5f;                 // Mask: alpha below it is cut away
    bool doubleSided = false;
};

// Triangles only: strips and fans are expanded at load; points and lines are dropped with a warning.
struct Primitive {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;    // always present: flat normals are computed when the file has none
    std::vector<glm::vec2> texcoords0; // empty when the primitive has no TEXCOORD_0
    std::vector<glm::vec2> texcoords1; // empty when the primitive has no TEXCOORD_1
    std::vector<glm::vec4> colors0;    // COLOR_0 as linear RGBA (alpha 1 for VEC3); empty when absent
    std::vector<std::uint32_t> indices;  // always present: 0..n-1 for non-indexed input
    int material = -1;                 // -1: the glTF default material (white, single-sided)
    glm::vec3 boundsMin{0.0f};
    glm::vec3 boundsMax{0.0f};
};

struct Mesh {
    std::string name;
    std::vector<Primitive> primitives;
};

enum class Projection { Perspective, Orthographic };

struct Camera {
    std::string name;
    Projection projection = Projection::Perspective;
    double yfov = 0.8;         // radians (perspective)
    double aspectRatio = 0.0;  // 0: follow the image (we always do; the file's value is kept for saving)
    double znear = 0.05;
    double zfar = 0.0;         // 0: infinite far plane
    double xmag = 1.0, ymag = 1.0;  // orthographic half extents
};

enum class LightType { Directional, Point, Spot };

// KHR_lights_punctual: directional intensity in lux, point/spot in candela.
struct Light {
    std::string name;
    LightType type = LightType::Directional;
    glm::vec3 color{1.0f};
    float intensity = 1.0f;
    double range = 0.0;  // 0: infinite
    double innerConeAngle = 0.0;
    double outerConeAngle = 0.7853981633974483;
};

struct Node {
    std::string name;
    int parent = -1;
    std::vector<int> children;
    // Rest pose. A node given as a matrix keeps it (and cannot be animated, as glTF requires).
    bool hasMatrix = false;
    glm::dmat4 matrix{1.0};
    glm::dvec3 translation{0.0};
    glm::dquat rotation{1.0, 0.0, 0.0, 0.0};  // w, x, y, z
    glm::dvec3 scale{1.0};
    int mesh = -1;
    int camera = -1;
    int light = -1;
    nlohmann::json extensions = nlohmann::json::object();  // every node extension, exactly as written
                                                           // (integers stay integers, empty objects stay)
};

enum class AnimationPath { Translation, Rotation, Scale };
enum class Interpolation { Linear, Step, CubicSpline };

struct AnimationChannel {
    int node = -1;
    AnimationPath path = AnimationPath::Translation;
    Interpolation interpolation = Interpolation::Linear;
    std::vector<float> times;       // strictly increasing
    std::vector<glm::vec4> values;  // xyz (translation, scale) or xyzw quaternion; cubic: in, value, out per key
};

struct Animation {
    std::string name;
    std::vector<AnimationChannel> channels;
};

// The root NIMBUS_participating_media values the engine itself needs (docs/design.md §4).
// Distance fog (scene-format.md §2.1, McReynolds and Blythe §8): what is seen at distance z along a ray is
// f·L + (1 − f)·color, with f from the mode (assets/fog.h).
enum class FogMode { None, Exp, Exp2, Linear, Height };

struct Fog {
    FogMode mode = FogMode::None;
    glm::dvec3 color{0.0};
    double density = 0.0;  // 1/m (exp, exp2, height at y = base)
    double start = 0.0;    // m (linear)
    double end = 0.0;      // m; how far rays that hit nothing see fog (linear: where f reaches 0)
    bool hasEnd = false;   // exp, exp2, height without `end`: the camera's far plane
    double base = 0.0;     // m (height): the world height where the density is `density`
    double falloff = 0.0;  // 1/m (height): density · e^(−falloff·(y − base))
};

// Which optical model the medium follows (the root `scattering` field, docs/scene-format.md §2):
// `multiple` is the radiative transfer equation (light scattered any number of times, ambient a
// uniform environment the medium attenuates and scatters); `single` is light scattered once, with
// ambient an unshadowed sky every point of the medium scatters.
enum class Scattering { Multiple, Single };

// A file without the root NIMBUS_participating_media object and without lights gets this ambient
// beside the default sun (docs/scene-format.md §4), as glTF viewers light such files.
inline constexpr float kDefaultAmbient = 0.3f;

struct Environment {
    glm::vec3 background{0.0f};  // radiance of rays that hit nothing
    glm::vec3 ambient{0.0f};     // multiple: the environment's radiance; single: unshadowed sky radiance
    bool defaultAmbient = false; // ambient is kDefaultAmbient because the file gives neither lights nor ambient
    Fog fog;
    Scattering scattering = Scattering::Multiple;
};

class Document;  // the parsed glTF file, kept for accessor reads and for saving

struct Scene {
    std::filesystem::path path;
    std::vector<Node> nodes;
    std::vector<int> rootNodes;  // nodes of the default scene (all parentless nodes when none is given)
    std::vector<Mesh> meshes;
    std::vector<Material> materials;
    std::vector<Texture> textures;
    std::vector<Image> images;
    std::vector<Camera> cameras;
    std::vector<Light> lights;
    std::vector<Animation> animations;
    Environment environment;
    nlohmann::json extensions = nlohmann::json::object();  // root extensions, as written
    std::shared_ptr<const Document> document;

    // The file name for messages ("scenes/smoke.gltf").
    std::string displayName() const;
};

// Loads .gltf or .glb (chosen by content, not by extension). Throws nimbus::InputError with one
// line naming file, object and field for anything malformed; never returns a partial scene.
// Buffers and images are data URIs or paths relative to the file (percent-encoding allowed);
// images are decoded with OpenImageIO (PNG, JPEG, WebP). POINTS and LINES primitives, morph
// target weights channels are dropped with a log::warn; channels without a target node are
// ignored, as glTF says.
Scene loadScene(const std::filesystem::path& file);

// The same for a file's bytes already in memory (the editor validates each edit this way): `file`
// is where the bytes would live, for relative URIs and for messages.
Scene loadSceneFromMemory(std::vector<unsigned char> bytes, const std::filesystem::path& file);

// Reads a FLOAT accessor with `components` per element (1 = SCALAR, 3 = VEC3, ...) for a plugin.
// `object` and `field` name where the reference came from, for the error message. Refuses an index
// out of range, a wrong type, a sparse or normalized accessor and non-finite values.
std::vector<float> readFloatAccessor(const Scene& scene, int accessor, int components, const std::string& object,
                                     const std::string& field);

// Number of elements of an accessor (for validation before reading); throws like readFloatAccessor.
std::size_t accessorCount(const Scene& scene, int accessor, const std::string& object, const std::string& field);

}  // namespace nimbus::assets
