#pragma once
// Cameras for the viewport tests.
#include <glm/gtc/matrix_transform.hpp>

#include "nimbus/assets/scene_queries.h"

namespace nimbus::sandbox::editor::testing {

inline assets::ResolvedCamera lookAt(const glm::dvec3& eye, const glm::dvec3& target, double yfov,
                                     const glm::dvec3& up = {0.0, 1.0, 0.0}) {
    assets::ResolvedCamera camera;
    camera.name = "test";
    camera.params.yfov = yfov;
    camera.world = glm::inverse(glm::lookAt(eye, target, up));
    return camera;
}

inline assets::ResolvedCamera orthographic(const glm::dvec3& eye, const glm::dvec3& target, double ymag) {
    assets::ResolvedCamera camera = lookAt(eye, target, 0.8);
    camera.params.projection = assets::Projection::Orthographic;
    camera.params.xmag = ymag;
    camera.params.ymag = ymag;
    return camera;
}

inline bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace nimbus::sandbox::editor::testing
