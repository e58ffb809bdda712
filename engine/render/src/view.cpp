#include "nimbus/render/view.h"

namespace nimbus::render {

View makeView(const assets::ResolvedCamera& camera, int width, int height) {
    const gpu::CameraPose pose = gpu::cameraPose(camera.world);
    if (camera.params.projection == assets::Projection::Orthographic)
        return gpu::makeOrthographicView(pose, camera.params.ymag, camera.params.znear, camera.params.zfar, width, height);
    return gpu::makePerspectiveView(pose, camera.params.yfov, camera.params.znear, camera.params.zfar, width, height);
}

}  // namespace nimbus::render
