#include "nimbus/render/view.h"

#include <cmath>
#include <limits>

namespace nimbus::render {

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

View makeView(const assets::ResolvedCamera& camera, int width, int height) {
    View v;
    v.width = width;
    v.height = height;
    v.origin = camera.position();
    v.forward = camera.forward();
    v.up = camera.up();
    v.right = camera.right();
    v.aspect = static_cast<float>(static_cast<double>(width) / static_cast<double>(height));
    v.znear = static_cast<float>(camera.params.znear);
    v.zfar = static_cast<float>(camera.params.zfar);

    // Rows of the rotation are the camera axes: the view matrix has no translation (eye at origin).
    glm::dmat4 view(1.0);
    for (int c = 0; c < 3; ++c) {
        view[c][0] = v.right[c];
        view[c][1] = v.up[c];
        view[c][2] = -v.forward[c];
    }
    v.view = glm::mat4(view);

    if (camera.params.projection == assets::Projection::Orthographic) {
        v.orthographic = true;
        v.orthoHalfExtent = glm::vec2(static_cast<float>(camera.params.ymag * v.aspect), static_cast<float>(camera.params.ymag));
        const double zfar = camera.params.zfar > camera.params.znear ? camera.params.zfar : camera.params.znear + 1e4;
        v.zfar = static_cast<float>(zfar);
        v.projection = reversedOrthographic(camera.params.ymag * v.aspect, camera.params.ymag, camera.params.znear, zfar);
    } else {
        v.tanHalfFovY = static_cast<float>(std::tan(camera.params.yfov * 0.5));
        v.projection = reversedPerspective(camera.params.yfov, static_cast<double>(width) / height, camera.params.znear,
                                           camera.params.zfar);
    }
    v.viewProjection = v.projection * v.view;
    v.inverseViewProjection = glm::inverse(v.viewProjection);
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

}  // namespace nimbus::render
