#pragma once
// Node animation in double precision: a channel sampled at time t, and a pose as a matrix.
#include <vector>

#include <glm/glm.hpp>

#include "gltf_scene.h"

namespace mini {

// The channel's value at t (xyz, or a unit quaternion xyzw), clamped to the first / last key
// outside the key range. LINEAR rotations take the shorter slerp.
glm::dvec4 sampleChannel(const Channel& channel, double t);

// Applies a sampled channel value to a pose.
void applyChannel(const Channel& channel, const glm::dvec4& value, Pose& pose);

// T · R · S.
glm::dmat4 poseMatrix(const Pose& pose);

// Every node's local-to-world matrix at `time`, outside the ECS: what the media plugin's glTF
// reader asks for at the many times an emitter is simulated over. The transform module computes
// the same matrices for the frame (same functions, same order of products).
std::vector<glm::dmat4> worldTransformsAt(const Scene& scene, double time);

}  // namespace mini
