#include "nimbus/base/camera_frame.h"

#include <cmath>

namespace nimbus {

glm::dvec3 unitOr(const glm::dvec3& v, const glm::dvec3& fallback) {
    const double length = glm::length(v);
    return length > 1e-300 && std::isfinite(length) ? v / length : fallback;
}

CameraFrame cameraFrame(const glm::dmat4& world) {
    CameraFrame f;
    f.forward = unitOr(-glm::dvec3(world[2]), {0.0, 0.0, -1.0});
    glm::dvec3 up = glm::dvec3(world[1]) - glm::dot(glm::dvec3(world[1]), f.forward) * f.forward;
    if (!(glm::length(up) > 1e-12 * glm::length(glm::dvec3(world[1]))) || !(glm::length(up) > 1e-300)) {
        // Y collapsed onto the view direction: any perpendicular will do.
        const glm::dvec3 helper = std::abs(f.forward.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
        up = helper - glm::dot(helper, f.forward) * f.forward;
    }
    f.up = glm::normalize(up);
    f.right = glm::cross(f.forward, f.up);
    return f;
}

}  // namespace nimbus
