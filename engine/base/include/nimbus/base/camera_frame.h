#pragma once
// A camera's axes from its world matrix, the one definition every renderer and host shares, so
// their rays agree bit for bit.
#include <glm/glm.hpp>

namespace nimbus {

// A unit vector along `v`, or `fallback` when v has no usable length (zero or non-finite scale).
glm::dvec3 unitOr(const glm::dvec3& v, const glm::dvec3& fallback);

// An orthonormal right-handed frame from a camera's world matrix: forward is local -Z, up is
// local +Y made perpendicular to it. Robust to (non-uniform) scale and shear.
struct CameraFrame {
    glm::dvec3 forward, up, right;
};
CameraFrame cameraFrame(const glm::dmat4& world);

}  // namespace nimbus
