#pragma once
// Sampling one animation channel at a time (glTF 2.0 Appendix C): STEP holds, LINEAR lerps
// (normalized shortest-path slerp for rotations), CUBICSPLINE evaluates the Hermite spline with
// the in/out tangents scaled by the key interval, then normalizes rotations. Outside the key
// range the first / last key value holds. All in double.
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "nimbus/assets/scene.h"

namespace nimbus::assets {

// xyz for translation / scale (w = 0), x, y, z, w for rotation (unit length).
glm::dvec4 sampleChannel(const AnimationChannel& channel, double timeSeconds);

// Normalized spherical interpolation of two quaternions stored as (x, y, z, w), shortest path.
glm::dvec4 slerpShortest(const glm::dvec4& a, const glm::dvec4& b, double s);

}  // namespace nimbus::assets
