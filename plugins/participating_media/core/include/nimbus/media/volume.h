#pragma once
// A volume of the medium (a node's `volume` object, docs/scene-format.md §3.6): a box or an
// ellipsoid of full extents `size` in the node's frame, centred on it, filled with the node's medium.
// Without noise its extinction is the constant σ and its optical depth along a ray the chord length
// times σ, exactly: the medium the judge is checked against closed forms with. With noise
// (noise_field.h) σ is scaled by the density field at each point, evaluated in the node's frame
// with the pattern shifted by `drift`, and optical depth has no closed form: volumeOpticalDepth
// integrates it by adaptive Simpson quadrature to a stated tolerance.
//
// Does not: move on its own (its node's transform at the frame's time is `world`; the noise's
// drift at that time is `drift`).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "nimbus/base/aabb.h"
#include "nimbus/media/noise_field.h"
#include "nimbus/media/particle_set.h"

namespace nimbus::media {

enum class VolumeShape : std::uint8_t { Box, Ellipsoid };

// A node's `volume` object as a scene declares it, before its node places it.
struct VolumeDesc {
    VolumeShape shape = VolumeShape::Box;
    glm::dvec3 size{1.0};  // full extents in the node's frame
    std::optional<NoiseField> noise;  // none: constant density
};

struct Volume {
    VolumeShape shape = VolumeShape::Box;
    glm::dmat4 world{1.0};   // node to world
    glm::dmat4 toLocal{1.0};  // world to node (makeVolume sets it)
    glm::dvec3 size{1.0};    // full extents in the node's frame
    Medium medium;           // extinction is σ (1/m): the constant, or the most the noise reaches
    std::string origin;      // where it was declared, for messages: file: node "name" (nodes[i])
    std::optional<NoiseField> noise;
    NoiseParams noiseParams;  // of `noise` for this shape (makeVolume sets them)
    glm::dvec3 drift{0.0};    // node frame: how far the pattern has moved (velocity × time)

    double sigma() const { return medium.extinction; }
};

Volume makeVolume(VolumeShape shape, const glm::dmat4& world, const glm::dvec3& size, const Medium& medium);
// `time` moves the noise by its velocity.
Volume makeVolume(const VolumeDesc& desc, const glm::dmat4& world, const Medium& medium, std::string origin, double time = 0.0);

// Where origin + t·dir (any length of dir; t in its units) is inside the volume: [enter, exit],
// enter > exit when the ray misses it. Either end may be negative (behind the origin).
struct VolumeChord {
    double enter = 1.0, exit = 0.0;
    bool hit() const { return exit > enter; }
};
VolumeChord volumeChord(const Volume& volume, const glm::dvec3& origin, const glm::dvec3& dir);

bool volumeContains(const Volume& volume, const glm::dvec3& point);

// σ_t at a world point: σ times the noise's density (σ without noise) inside, 0 outside.
double volumeExtinction(const Volume& volume, const glm::dvec3& point);
// Where the noise is read for a world point: the noise-space point (node metres less the drift,
// times the frequency) and the point in the shape's unit frame. Both as the GPU's float vectors.
struct NoisePoint {
    glm::vec3 p{0.0f}, unit{0.0f};
};
NoisePoint noisePoint(const Volume& volume, const glm::dvec3& point);

// The optical depth along origin + t·dir (dir of any length, t in its units) over [t0, t1], clipped
// to the volume: σ × length without noise; with noise, adaptive Simpson quadrature from a start at
// four intervals per cycle of the finest octave, refined until each interval's estimate changes by
// less than `tolerance` × its own optical depth plus 1e-12.
double volumeOpticalDepth(const Volume& volume, const glm::dvec3& origin, const glm::dvec3& dir, double t0, double t1,
                          double tolerance = 1e-6);
// The starting intervals of that quadrature over `length` (dir's units) of a noise volume.
int volumeQuadratureIntervals(const Volume& volume, const glm::dvec3& dir, double length);
Aabb volumeBounds(const Volume& volume);
Aabb volumeBounds(const std::vector<Volume>& volumes);

}  // namespace nimbus::media
