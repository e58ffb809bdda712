#pragma once
// The ray through a pixel centre: the convention the reference and the real-time renderer share, so
// their images compare pixel for pixel.
//
// Pixel (x, y), row 0 at the top, one ray through the centre (x + 0.5, y + 0.5), no anti-aliasing.
//   ndcX = 2(x + 0.5)/W - 1,  ndcY = 1 - 2(y + 0.5)/H
// Perspective: aspect = W/H (the file's aspectRatio is ignored), tanHalf = tan(yfov/2),
//   origin = camera position, dir = normalize(forward + right·ndcX·tanHalf·aspect + up·ndcY·tanHalf).
// Orthographic: origin = position + right·xmag·ndcX + up·ymag·ndcY, dir = forward.
// Near/far planes clip meshes like the rasteriser: a mesh hit counts only when its view depth
// dot(hit - eye, forward) is in [znear, zfar] (zfar = 0: infinite). Along the ray that is
// t in [meshNear, meshFar] with meshNear = znear / dot(dir, forward). The medium is integrated from
// the eye (t = 0) to the mesh hit, or to meshFar (+inf with no far plane) when nothing is hit.
#include <glm/glm.hpp>

#include "nimbus/assets/scene_queries.h"

namespace nimbus::media::reference {

struct CameraRay {
    glm::dvec3 origin{0.0};
    glm::dvec3 direction{0.0, 0.0, -1.0};  // unit
    double meshNear = 0.0;                  // first t at which a mesh hit counts
    double meshFar = 0.0;                   // last t (may be +inf)
};

// The camera basis, computed once per image (ResolvedCamera's frame is orthonormal).
struct CameraFrame {
    glm::dvec3 position{0.0}, forward{0.0, 0.0, -1.0}, up{0.0, 1.0, 0.0}, right{1.0, 0.0, 0.0};
    assets::Camera params;
    int width = 1, height = 1;
};

CameraFrame makeCameraFrame(const assets::ResolvedCamera& camera, int width, int height);

CameraRay cameraRay(const CameraFrame& frame, int x, int y);

}  // namespace nimbus::media::reference
