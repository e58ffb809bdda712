#include "nimbus/media/reference/camera_rays.h"

#include <cmath>
#include <limits>

namespace nimbus::media::reference {

CameraFrame makeCameraFrame(const assets::ResolvedCamera& camera, int width, int height) {
    CameraFrame f;
    f.position = camera.position();
    f.forward = camera.forward();
    f.up = camera.up();
    f.right = camera.right();
    f.params = camera.params;
    f.width = width;
    f.height = height;
    return f;
}

CameraRay cameraRay(const CameraFrame& f, int x, int y) {
    const double ndcX = 2.0 * (x + 0.5) / f.width - 1.0;
    const double ndcY = 1.0 - 2.0 * (y + 0.5) / f.height;
    CameraRay ray;
    if (f.params.projection == assets::Projection::Orthographic) {
        // The image aspect follows the output size (docs/design.md §4), as in render::makeView: ymag·W/H wide.
        const double aspect = static_cast<double>(f.width) / static_cast<double>(f.height);
        ray.origin = f.position + f.right * (f.params.ymag * aspect * ndcX) + f.up * (f.params.ymag * ndcY);
        ray.direction = f.forward;
    } else {
        const double tanHalf = std::tan(0.5 * f.params.yfov);
        const double aspect = static_cast<double>(f.width) / static_cast<double>(f.height);
        ray.origin = f.position;
        ray.direction = glm::normalize(f.forward + f.right * (ndcX * tanHalf * aspect) + f.up * (ndcY * tanHalf));
    }
    const double cosine = glm::dot(ray.direction, f.forward);  // > 0 for any pixel of a sane camera
    ray.meshNear = std::max(0.0, f.params.znear) / cosine;
    ray.meshFar = f.params.zfar > 0.0 ? f.params.zfar / cosine : std::numeric_limits<double>::infinity();
    return ray;
}

}  // namespace nimbus::media::reference
