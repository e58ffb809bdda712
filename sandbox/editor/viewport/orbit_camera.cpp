#include "viewport/orbit_camera.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/constants.hpp>

namespace nimbus::sandbox::editor {
namespace {

constexpr double kRadiansPerPixel = 0.01;
constexpr double kZoomPerStep = 0.85;
constexpr double kMinDistance = 1e-3;

double clampPitch(double pitch) {
    if (!std::isfinite(pitch)) return 0.0;
    return std::clamp(pitch, -OrbitCamera::kMaxPitch, OrbitCamera::kMaxPitch);
}

double clampDistance(double distance) { return std::isfinite(distance) ? std::max(distance, kMinDistance) : 5.0; }

// Unit vector from the target to the camera.
glm::dvec3 backward(double yaw, double pitch) {
    return {std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw)};
}

// Heading of a camera: from its horizontal view direction, or from its up vector when it looks
// (almost) straight up or down, so that the picture does not spin when orbiting starts.
double headingOf(const glm::dvec3& back, const glm::dvec3& up) {
    glm::dvec2 horizontal(back.x, back.z);
    if (glm::length(horizontal) < 1e-6) horizontal = (back.y > 0.0 ? -1.0 : 1.0) * glm::dvec2(up.x, up.z);
    if (glm::length(horizontal) < 1e-12) return 0.0;
    return std::atan2(horizontal.x, horizontal.y);
}

}  // namespace

OrbitCamera OrbitCamera::fromCamera(const assets::ResolvedCamera& camera, double focusDistance) {
    OrbitCamera orbit;
    const glm::dvec3 back = -camera.forward();
    orbit.yaw = headingOf(back, camera.up());
    orbit.pitch = clampPitch(std::asin(std::clamp(back.y, -1.0, 1.0)));
    orbit.distance = clampDistance(focusDistance);
    if (camera.params.projection == assets::Projection::Orthographic) {
        // Same visible height at the focus distance.
        orbit.yfov = 2.0 * std::atan(std::abs(camera.params.ymag) / orbit.distance);
    } else if (std::isfinite(camera.params.yfov) && camera.params.yfov > 0.0) {
        orbit.yfov = camera.params.yfov;
    }
    if (camera.params.znear > 0.0) orbit.znear = camera.params.znear;
    orbit.zfar = std::max(0.0, camera.params.zfar);
    // From the (possibly clamped) direction, so the camera keeps its position exactly.
    orbit.target = camera.position() - backward(orbit.yaw, orbit.pitch) * orbit.distance;
    return orbit;
}

void OrbitCamera::orbit(double dxPixels, double dyPixels) {
    // Dragging right turns the scene right (the camera goes left); dragging down lifts the camera.
    yaw -= dxPixels * kRadiansPerPixel;
    if (!std::isfinite(yaw)) yaw = 0.0;
    yaw = std::remainder(yaw, 2.0 * glm::pi<double>());
    pitch = clampPitch(pitch + dyPixels * kRadiansPerPixel);
}

void OrbitCamera::pan(double dxPixels, double dyPixels, int viewportHeight) {
    const double worldPerPixel = 2.0 * distance * std::tan(0.5 * yfov) / std::max(1, viewportHeight);
    const assets::ResolvedCamera camera = resolved();
    const glm::dvec3 delta = camera.right() * (-dxPixels * worldPerPixel) + camera.up() * (dyPixels * worldPerPixel);
    if (std::isfinite(delta.x) && std::isfinite(delta.y) && std::isfinite(delta.z)) target += delta;
}

void OrbitCamera::zoom(double wheelSteps) { distance = clampDistance(distance * std::pow(kZoomPerStep, wheelSteps)); }

void OrbitCamera::frame(const Aabb& box) {
    if (box.empty()) return;
    const double radius = 0.5 * glm::length(box.extent());
    if (!std::isfinite(radius)) return;
    target = box.center();
    const double halfFov = std::clamp(0.5 * yfov, 1e-3, 1.5);
    distance = clampDistance(std::max(radius / std::sin(halfFov), 10.0 * znear));
}

glm::dvec3 OrbitCamera::position() const { return target + backward(yaw, pitch) * distance; }

glm::dvec3 OrbitCamera::forward() const { return -backward(yaw, pitch); }

assets::ResolvedCamera OrbitCamera::resolved() const {
    const glm::dvec3 back = backward(yaw, pitch);
    const glm::dvec3 right(std::cos(yaw), 0.0, -std::sin(yaw));  // cos(pitch) > 0: never degenerate
    const glm::dvec3 up = glm::cross(back, right);
    assets::ResolvedCamera camera;
    camera.name = "editor";
    camera.params.name = "editor";
    camera.params.projection = assets::Projection::Perspective;
    camera.params.yfov = yfov;
    camera.params.znear = znear;
    camera.params.zfar = zfar;
    camera.world = glm::dmat4(glm::dvec4(right, 0.0), glm::dvec4(up, 0.0), glm::dvec4(back, 0.0),
                              glm::dvec4(position(), 1.0));
    camera.synthesized = false;
    return camera;
}

}  // namespace nimbus::sandbox::editor
