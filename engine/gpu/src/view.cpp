#include "nimbus/gpu/view.h"

#include <cmath>
#include <limits>

#include "nimbus/base/camera_frame.h"

namespace nimbus::gpu {

glm::mat4 reversedPerspective(double yfov, double aspect, double znear, double zfar) {
    const double f = 1.0 / std::tan(yfov * 0.5);
    // clip.z = a·z_view + b, clip.w = −z_view, so depth = 1 at −near and 0 at −far (or infinity).
    const double a = zfar > 0.0 ? znear / (zfar - znear) : 0.0;
    const double b = zfar > 0.0 ? znear * zfar / (zfar - znear) : znear;
    glm::dmat4 p(0.0);
    p[0][0] = f / aspect;
    p[1][1] = f;
    p[2][2] = a;
    p[2][3] = -1.0;
    p[3][2] = b;
    return glm::mat4(p);
}

glm::mat4 reversedOrthographic(double halfWidth, double halfHeight, double znear, double zfar) {
    glm::dmat4 p(1.0);
    p[0][0] = 1.0 / halfWidth;
    p[1][1] = 1.0 / halfHeight;
    // depth = (z_view + far) / (far − near): 1 at −near, 0 at −far.
    p[2][2] = 1.0 / (zfar - znear);
    p[3][2] = zfar / (zfar - znear);
    return glm::mat4(p);
}

namespace {

// Rows of the rotation are the camera axes: the view matrix has no translation (eye at origin).
View poseView(const CameraPose& pose, int width, int height, double znear, double zfar) {
    View v;
    v.width = width;
    v.height = height;
    v.origin = pose.position;
    v.forward = pose.forward;
    v.up = pose.up;
    v.right = pose.right;
    v.aspect = static_cast<float>(static_cast<double>(width) / static_cast<double>(height));
    v.znear = static_cast<float>(znear);
    v.zfar = static_cast<float>(zfar);
    glm::dmat4 view(1.0);
    for (int c = 0; c < 3; ++c) {
        view[c][0] = v.right[c];
        view[c][1] = v.up[c];
        view[c][2] = -v.forward[c];
    }
    v.view = glm::mat4(view);
    return v;
}

void finish(View& v) {
    v.viewProjection = v.projection * v.view;
    v.inverseViewProjection = glm::inverse(v.viewProjection);
}

}  // namespace

CameraPose cameraPose(const glm::dmat4& world) {
    const CameraFrame frame = cameraFrame(world);
    return {glm::dvec3(world[3]), frame.forward, frame.up, frame.right};
}

View makePerspectiveView(const CameraPose& pose, double yfov, double znear, double zfar, int width, int height) {
    View v = poseView(pose, width, height, znear, zfar);
    v.tanHalfFovY = static_cast<float>(std::tan(yfov * 0.5));
    v.projection = reversedPerspective(yfov, static_cast<double>(width) / height, znear, zfar);
    finish(v);
    return v;
}

View makeOrthographicView(const CameraPose& pose, double ymag, double znear, double zfar, int width, int height) {
    zfar = zfar > znear ? zfar : znear + 1e4;
    View v = poseView(pose, width, height, znear, zfar);
    v.orthographic = true;
    v.orthoHalfExtent = glm::vec2(static_cast<float>(ymag * v.aspect), static_cast<float>(ymag));
    v.projection = reversedOrthographic(ymag * v.aspect, ymag, znear, zfar);
    finish(v);
    return v;
}

glm::vec2 View::depthLinearization() const {
    if (orthographic) return {znear, zfar};
    const double n = znear, f = zfar;
    const double a = f > 0.0 ? n / (f - n) : 0.0;
    const double b = f > 0.0 ? n * f / (f - n) : n;
    return {static_cast<float>(a), static_cast<float>(b)};
}

double View::viewDepth(float d) const {
    if (orthographic) return znear + (1.0 - d) * (static_cast<double>(zfar) - znear);
    const glm::vec2 ab = depthLinearization();
    const double denom = static_cast<double>(d) + ab.x;
    return denom > 0.0 ? ab.y / denom : std::numeric_limits<double>::infinity();
}

}  // namespace nimbus::gpu
