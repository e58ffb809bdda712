#pragma once
// What the renderers ask of a loaded scene at a given time: world transforms (with animation),
// bounds, the render camera and the lights, resolved to world space in double precision.
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "nimbus/assets/scene.h"
#include "nimbus/base/aabb.h"

namespace nimbus::assets {

using nimbus::Aabb;

// Which nodes belong to the scene that is shown: the subtrees of Scene::rootNodes. Nodes outside
// (other glTF scenes, orphans when the file names a default scene) are not drawn, framed or lit.
std::vector<bool> nodesInScene(const Scene& scene);

// A node's rest-pose local matrix (its matrix, or T·R·S).
glm::dmat4 localTransform(const Node& node);

// Local-to-world matrix of every node at `timeSeconds` (animations clamp outside their key range).
std::vector<glm::dmat4> computeWorldTransforms(const Scene& scene, double timeSeconds);

// World-space bounds of every mesh instance in the scene (primitive boxes transformed, so conservative).
Aabb meshBounds(const Scene& scene, const std::vector<glm::dmat4>& world);

// A camera placed in the world. `synthesized` when the scene had none and one was made to frame it.
struct ResolvedCamera {
    std::string name;
    Camera params;
    glm::dmat4 world{1.0};  // camera looks down its local -Z, +Y up (glTF)
    bool synthesized = false;

    glm::dvec3 position() const { return glm::dvec3(world[3]); }
    glm::dvec3 forward() const;  // unit, world space
    glm::dvec3 up() const;       // unit, world space
    glm::dvec3 right() const;    // unit, world space
};

// The scene's first camera (lowest node index in the scene carrying one), or the camera whose camera name or node
// name is `name`, or else, when `name` is a decimal number, the first node carrying cameras[name]
// (unnamed cameras are picked by index). With no camera in the scene and no name asked, one is
// made that frames `frame` (the caller passes mesh bounds plus anything else visible, e.g. media).
// Throws InputError when `name` matches nothing, listing the cameras by index and name.
ResolvedCamera resolveCamera(const Scene& scene, const std::vector<glm::dmat4>& world, std::string_view name,
                             const Aabb& frame, double aspect);

// A light placed in the world. Directional and spot lights shine along `direction` (node -Z).
struct ResolvedLight {
    std::string name;
    Light params;
    glm::dvec3 position{0.0};
    glm::dvec3 direction{0.0, 0.0, -1.0};  // unit; the direction light travels
    bool synthesized = false;
};

// Every light in the scene; a scene with none gets the documented default sun (docs/scene-format.md):
// directional, white, 3 lux, travelling along normalize(-0.4, -1.0, -0.3).
std::vector<ResolvedLight> resolveLights(const Scene& scene, const std::vector<glm::dmat4>& world);

}  // namespace nimbus::assets
