#pragma once
// The editor viewport's camera: orbits, pans and zooms about a target point, and hands the renderers
// an ordinary ResolvedCamera.
//
// Does not: read input devices (the viewport passes mouse deltas in), or animate.
#include <glm/glm.hpp>

#include "nimbus/assets/scene_queries.h"
#include "nimbus/base/aabb.h"

namespace nimbus::sandbox::editor {

struct OrbitCamera {
    glm::dvec3 target{0.0};
    double distance = 5.0;  // > 0
    double yaw = 0.0;       // radians about +Y; 0 puts the camera on +Z of the target, looking down -Z
    double pitch = 0.3;     // radians, clamped to (-kMaxPitch, kMaxPitch); > 0 is above the target
    double yfov = 0.8;      // radians
    double znear = 0.05;
    double zfar = 0.0;      // 0: infinite

    static constexpr double kMaxPitch = 1.55;

    // Start orbiting from a scene camera: same position, direction and field of view; the target lies
    // `focusDistance` ahead of it. Looking straight up/down is clamped to kMaxPitch (position kept).
    static OrbitCamera fromCamera(const assets::ResolvedCamera& camera, double focusDistance);

    void orbit(double dxPixels, double dyPixels);                    // drag: 0.01 rad per pixel
    void pan(double dxPixels, double dyPixels, int viewportHeight);  // the point at the target's depth follows the mouse
    void zoom(double wheelSteps);                                     // distance *= 0.85^steps, >= 1e-3
    void frame(const Aabb& box);  // the box's bounding sphere fits yfov (and the width when wider than tall); same direction

    glm::dvec3 position() const;
    glm::dvec3 forward() const;  // unit, from the camera towards the target
    assets::ResolvedCamera resolved() const;  // "editor", perspective, not synthesized, rigid world matrix
};

}  // namespace nimbus::sandbox::editor
