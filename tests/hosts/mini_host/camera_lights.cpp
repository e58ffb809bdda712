#include "camera_lights.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace mini {
namespace gpu = nimbus::gpu;
namespace {

// v / |v|, or `fallback` when v has no usable length (a zero or non-finite scale).
glm::dvec3 unitOr(const glm::dvec3& v, const glm::dvec3& fallback) {
    const double length = glm::length(v);
    return length > 1e-300 && std::isfinite(length) ? v / length : fallback;
}

}  // namespace

gpu::CameraPose cameraPose(const glm::dmat4& world) {
    gpu::CameraPose pose;
    pose.position = glm::dvec3(world[3]);
    pose.forward = unitOr(-glm::dvec3(world[2]), {0.0, 0.0, -1.0});
    const glm::dvec3 y(world[1]);
    glm::dvec3 up = y - glm::dot(y, pose.forward) * pose.forward;
    if (!(glm::length(up) > 1e-12 * glm::length(y)) || !(glm::length(up) > 1e-300)) {
        // +Y collapsed onto the view direction: any perpendicular will do.
        const glm::dvec3 helper = std::abs(pose.forward.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
        up = helper - glm::dot(helper, pose.forward) * pose.forward;
    }
    pose.up = glm::normalize(up);
    pose.right = glm::cross(pose.forward, pose.up);
    return pose;
}

gpu::View cameraView(const Camera& camera, const glm::dmat4& world, int width, int height) {
    const gpu::CameraPose pose = cameraPose(world);
    if (camera.orthographic) return gpu::makeOrthographicView(pose, camera.ymag, camera.znear, camera.zfar, width, height);
    return gpu::makePerspectiveView(pose, camera.yfov, camera.znear, camera.zfar, width, height);
}

void framingCamera(const nimbus::Aabb& frame, double aspect, Camera& camera, glm::dmat4& world) {
    camera = Camera{};
    camera.yfov = 0.8;
    const glm::dvec3 centre = frame.empty() ? glm::dvec3(0.0) : frame.center();
    double radius = frame.empty() ? 1.0 : 0.5 * glm::length(frame.extent());
    if (!(radius > 0.0) || !std::isfinite(radius)) radius = 1.0;
    const double a = aspect > 0.0 && std::isfinite(aspect) ? aspect : 1.0;
    const double halfV = 0.5 * camera.yfov;
    const double halfH = std::atan(std::tan(halfV) * a);
    const double distance = 1.05 * radius / std::sin(std::min(halfV, halfH));
    const glm::dvec3 eye = centre + distance * glm::normalize(glm::dvec3(1.0, 0.6, 1.4));
    world = glm::inverse(glm::lookAt(eye, centre, glm::dvec3(0.0, 1.0, 0.0)));
    camera.znear = std::max(0.5 * (distance - radius), 1e-4 * distance);
    camera.zfar = 2.0 * (distance + radius);
}

gpu::PunctualLight placeLight(const Light& light, const glm::dmat4& world) {
    gpu::PunctualLight p;
    p.kind = light.kind;
    p.position = glm::dvec3(world[3]);
    p.direction = unitOr(glm::dvec3(world * glm::dvec4(0.0, 0.0, -1.0, 0.0)), {0.0, 0.0, -1.0});
    p.radiance = light.color * light.intensity;
    p.range = light.range;
    p.innerConeAngle = light.innerConeAngle;
    p.outerConeAngle = light.outerConeAngle;
    return p;
}

gpu::PunctualLight defaultSun() {
    gpu::PunctualLight sun;
    sun.kind = gpu::LightKind::Directional;
    sun.direction = glm::normalize(glm::dvec3(-0.4, -1.0, -0.3));
    sun.radiance = glm::vec3(1.0f) * 3.0f;
    return sun;
}

}  // namespace mini
