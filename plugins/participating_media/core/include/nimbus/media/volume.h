#pragma once
// A volume of the medium (a node's `volume` object, docs/scene-format.md): a box or an ellipsoid of
// full extents `size` in the node's frame, centred on it, filled with the node's medium at its
// constant extinction. Its optical depth along a ray is the chord length times σ, exactly, which
// makes it the medium the judge is checked against closed forms with.
//
// Does not: vary in density (noise volumes add a density field later), or move on its own (its
// node's transform at the frame's time is `world`).
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "nimbus/base/aabb.h"
#include "nimbus/media/particle_set.h"

namespace nimbus::media {

enum class VolumeShape : std::uint8_t { Box, Ellipsoid };

// A node's `volume` object as a scene declares it, before its node places it.
struct VolumeDesc {
    VolumeShape shape = VolumeShape::Box;
    glm::dvec3 size{1.0};  // full extents in the node's frame
};

struct Volume {
    VolumeShape shape = VolumeShape::Box;
    glm::dmat4 world{1.0};   // node to world
    glm::dmat4 toLocal{1.0};  // world to node (makeVolume sets it)
    glm::dvec3 size{1.0};    // full extents in the node's frame
    Medium medium;           // extinction is σ (1/m), constant inside
    std::string origin;      // where it was declared, for messages: file: node "name" (nodes[i])

    double sigma() const { return medium.extinction; }
};

Volume makeVolume(VolumeShape shape, const glm::dmat4& world, const glm::dvec3& size, const Medium& medium);
Volume makeVolume(const VolumeDesc& desc, const glm::dmat4& world, const Medium& medium, std::string origin);

// Where origin + t·dir (any length of dir; t in its units) is inside the volume: [enter, exit],
// enter > exit when the ray misses it. Either end may be negative (behind the origin).
struct VolumeChord {
    double enter = 1.0, exit = 0.0;
    bool hit() const { return exit > enter; }
};
VolumeChord volumeChord(const Volume& volume, const glm::dvec3& origin, const glm::dvec3& dir);

bool volumeContains(const Volume& volume, const glm::dvec3& point);
Aabb volumeBounds(const Volume& volume);
Aabb volumeBounds(const std::vector<Volume>& volumes);

}  // namespace nimbus::media
