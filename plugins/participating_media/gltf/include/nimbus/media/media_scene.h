#pragma once
// The media a glTF scene declares: each node's "NIMBUS_participating_media" object (docs/design.md §4),
// parsed and validated, and turned into world-space particles for a given time.
//
// Node object keys: "medium" (required), "particles" (a static cloud in the node's local frame),
// "generator" (a static cloud made from a seed: cloud_generator.h), "volume" (a box or ellipsoid of
// the medium, constant or with noise), "emitter" and "render" (kept as raw JSON for the systems that
// own them). Anything else is refused.
//   medium:    extinction > 0 (required), albedo [r,g,b] in [0,1] (default [1,1,1]), g in (-1,1)
//              (default 0), emission [r,g,b] >= 0 (default 0), phase "henyey-greenstein" | "rayleigh".
//   particles: position (accessor VEC3 float), radius (accessor SCALAR float, > 0),
//              density (optional accessor SCALAR float, >= 0, default 1); equal counts.
//   volume:    shape "box" | "ellipsoid" (required), size [x, y, z] > 0 (required): full extents in
//              the node's frame, centred on it.
// Every refusal is one nimbus::InputError naming the file, the node (index and name) and the field.
//
// Does not: simulate emitters (that system extends particlesAtTime); read the root object
// (background/ambient belong to assets::Environment).
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "nimbus/media/gltf_document.h"
#include "nimbus/media/particle_set.h"
#include "nimbus/media/volume.h"

namespace nimbus::media {

// More particles than this in one node is refused as an absurd count (it would need gigabytes).
inline constexpr std::size_t kMaxParticlesPerNode = std::size_t{1} << 24;

struct MediaNode {
    int node = -1;
    std::string name;
    Medium medium;
    std::vector<glm::vec3> localPositions;  // the node's local frame (from `particles` or `generator`)
    std::vector<float> radii;
    std::vector<float> densities;  // same count as localPositions (1 where the file gave none)
    std::optional<VolumeDesc> volume;  // a `volume` object
    std::string origin;                // file: node "name" (nodes[i]), for the renderers' messages
    nlohmann::json emitter;        // null when absent
    nlohmann::json render;         // null when absent
};

struct MediaScene {
    std::vector<MediaNode> nodes;  // in node index order
    bool empty() const { return nodes.empty(); }
};

// Parses every node's extension object. Throws nimbus::InputError on anything malformed.
MediaScene parseMediaScene(const GltfDocument& scene);

// World-space particles of the static clouds: position = world[node]·p (double), radius × the node's
// uniform scale (cbrt|det| of the 3×3 part; a warning is logged when the scale is not uniform),
// sigma = extinction · density. Particles with density 0 are left out.
ParticleSet staticParticles(const MediaScene& media, const std::vector<glm::dmat4>& world);

// Appends one static cloud's particles placed by `world` (the one definition both the ECS adapter
// and staticParticles use, so they agree bit for bit): radius × cbrt|det(world)|, sigma =
// extinction · density; density ≤ 0 is left out. `densities` may be empty (all 1).
void appendCloudParticles(ParticleSet& out, const Medium& medium, const std::vector<glm::vec3>& positions,
                          const std::vector<float>& radii, const std::vector<float>& densities, const glm::dmat4& world);

// Whether `world` scales uniformly (spheres stay spheres); callers warn when it does not.
bool hasUniformScale(const glm::dmat4& world);

// The volumes of the scene placed by `world` (a node's world transform, per node index), each
// naming its node in Volume::origin, its noise drifted to `time`.
std::vector<Volume> sceneVolumes(const MediaScene& media, const std::vector<glm::dmat4>& world, double time = 0.0);

// Every particle of the scene at `timeSeconds` for hosts without the ECS: the static clouds posed at
// that time, then every emitter simulated from 0 (simulateEmittersTo), in node order — exactly the
// set the ECS adapter gathers after stepping the App to the same time.
ParticleSet particlesAtTime(const GltfDocument& scene, const MediaScene& media, double timeSeconds);

}  // namespace nimbus::media
