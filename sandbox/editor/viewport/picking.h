#pragma once
// Viewport rays and projections with the renderers' pixel convention (row 0 at the top, pixel centres at
// +0.5; see reference/camera_rays.h), and ray tests against boxes and spheres for picking.
//
// Does not: test triangles (node bounds are picked, not their meshes), or know about the scene.
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "nimbus/assets/scene_queries.h"
#include "nimbus/base/aabb.h"

namespace nimbus::sandbox::editor {

struct Ray {
    glm::dvec3 origin{0.0};
    glm::dvec3 direction{0.0, 0.0, -1.0};  // unit from viewportRay; any non-zero length for the intersections
};

// The ray through a point of the viewport in pixels (x right, y DOWN, (0,0) the top-left corner; pixel
// centres at +0.5) of a width×height image, for perspective and orthographic cameras.
Ray viewportRay(const assets::ResolvedCamera& camera, glm::dvec2 pixel, int width, int height);

// Where a world point appears in the viewport (same pixel convention); nullopt behind the camera
// (view depth <= 0) or when the result would not be finite.
std::optional<glm::dvec2> projectToViewport(const assets::ResolvedCamera& camera, const glm::dvec3& world, int width,
                                            int height);

// The view depth of a world point: its distance along the camera's forward axis.
double viewDepth(const assets::ResolvedCamera& camera, const glm::dvec3& world);

// World units per viewport pixel at view depth `depth` (constant for orthographic cameras).
double worldPerPixel(const assets::ResolvedCamera& camera, double depth, int height);

// Ray parameter of the first hit with the box (0 when the origin is inside); nullopt for a miss.
std::optional<double> intersectAabb(const Ray& ray, const Aabb& box);
// Ray parameter of the first hit with the sphere (0 when the origin is inside); nullopt for a miss.
std::optional<double> intersectSphere(const Ray& ray, const glm::dvec3& centre, double radius);

// A pickable thing: an id (the editor uses node indices), a world box, or a sphere (lights and cameras as icons).
struct PickTarget {
    int id = -1;
    Aabb box;
    bool sphere = false;
    glm::dvec3 centre{0.0};
    double radius = 0.0;
};

// The id of the nearest target hit (the first listed on a tie); -1 when none. A sphere the ray starts
// inside is not hit: an icon around the eye is the camera the view looks through, not on screen.
// (A box the ray starts inside is hit at 0: the eye inside a cloud picks the cloud.)
int pick(const Ray& ray, const std::vector<PickTarget>& targets);

// The 8 corners of `box` transformed by `world` as a world-space Aabb (empty stays empty).
Aabb transformBox(const Aabb& box, const glm::dmat4& world);

}  // namespace nimbus::sandbox::editor
