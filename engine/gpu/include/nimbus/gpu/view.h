#pragma once
// The camera as the GPU sees it. Every position sent to the GPU is relative to `origin` (the camera
// position, in double), so scenes far from the world origin keep full float precision. Projections
// use reversed Z with [0, 1] clip depth (glClipControl): depth 1 at the near plane, 0 at the far
// plane or at infinity, which keeps depth precision far from the camera.
//
// Pixel (x, y) of the image (row 0 at the top) sees the same ray as the reference renderer:
// dir ∝ forward + right·(2(x+0.5)/W − 1)·tan(yfov/2)·W/H + up·(1 − 2(y+0.5)/H)·tan(yfov/2).
#include <glm/glm.hpp>

namespace nimbus::gpu {

struct View {
    int width = 0;
    int height = 0;
    glm::dvec3 origin{0.0};        // world position every GPU coordinate is relative to
    glm::mat4 view{1.0f};          // origin-relative world → view (a rotation: the eye is at the origin)
    glm::mat4 projection{1.0f};    // view → clip, reversed Z
    glm::mat4 viewProjection{1.0f};
    glm::mat4 inverseViewProjection{1.0f};
    glm::dvec3 forward{0, 0, -1}, right{1, 0, 0}, up{0, 1, 0};
    bool orthographic = false;
    float znear = 0.05f;
    float zfar = 0.0f;             // 0: infinite
    float tanHalfFovY = 0.0f;      // perspective
    float aspect = 1.0f;
    glm::vec2 orthoHalfExtent{1.0f};

    // Depth-buffer value → view depth (distance along forward); +inf for the cleared background.
    double viewDepth(float depthBufferValue) const;
    // Constants the shaders use for the same conversion: depth = b / (d + a) (perspective) or
    // depth = near + (1 − d)(far − near) (orthographic).
    glm::vec2 depthLinearization() const;

    glm::vec3 toRelative(const glm::dvec3& world) const { return glm::vec3(world - origin); }
};

// A camera at `position` with orthonormal axes (glTF cameras look down their −Z): perspective with
// vertical field of view `yfov` (zfar 0: infinite), or orthographic with half height `ymag`
// (zfar ≤ znear: znear + 10⁴). The aspect is width / height.
struct CameraPose {
    glm::dvec3 position{0.0};
    glm::dvec3 forward{0, 0, -1}, up{0, 1, 0}, right{1, 0, 0};
};
// The pose of a camera node from its world matrix (nimbus/base/camera_frame.h).
CameraPose cameraPose(const glm::dmat4& world);
View makePerspectiveView(const CameraPose& pose, double yfov, double znear, double zfar, int width, int height);
View makeOrthographicView(const CameraPose& pose, double ymag, double znear, double zfar, int width, int height);

// Reversed-Z projections. zfar = 0 gives an infinite far plane (perspective only).
glm::mat4 reversedPerspective(double yfov, double aspect, double znear, double zfar);
glm::mat4 reversedOrthographic(double halfWidth, double halfHeight, double znear, double zfar);

}  // namespace nimbus::gpu
