#pragma once
// Cameras and lights placed in the world, following docs/scene-format.md §4 (render camera, aspect
// from the image, default sun, framing camera) with Nimbus's exact arithmetic, so both hosts build
// bit-identical view matrices from the same file.
#include <glm/glm.hpp>

#include "gltf_scene.h"
#include "nimbus/base/aabb.h"
#include "nimbus/gpu/light_views.h"
#include "nimbus/gpu/view.h"

namespace mini {

// An orthonormal camera frame from a world matrix: forward = −Z column, up = +Y column made
// perpendicular to forward, right = forward × up (robust to scale and shear).
nimbus::gpu::CameraPose cameraPose(const glm::dmat4& world);

// The view of `camera` at `world` for a width × height image (the file's aspectRatio is ignored).
nimbus::gpu::View cameraView(const Camera& camera, const glm::dmat4& world, int width, int height);

// With no camera in the scene: look at the centre of `frame` from (+1, +0.6, +1.4), yfov 0.8, far
// enough back that its bounding sphere fits both fields of view. Sets `camera` and `world`.
void framingCamera(const nimbus::Aabb& frame, double aspect, Camera& camera, glm::dmat4& world);

// A scene light on a node: position = the node's world translation, direction = its world −Z.
nimbus::gpu::PunctualLight placeLight(const Light& light, const glm::dmat4& world);

// The light of a scene without lights: directional, white, 3 lux, along normalize(−0.4, −1, −0.3).
nimbus::gpu::PunctualLight defaultSun();

}  // namespace mini
