#pragma once
// Views from a light: used for mesh shadow maps and, by the media plugin, for transmittance slices.
// A directional light gets one orthographic view fitted around the bounds it must cover, a spot
// light one perspective view along its axis, a point light six 90° cube-face views.
// All matrices map origin-relative world positions (see View), never absolute ones.
#include <vector>

#include <glm/glm.hpp>

#include "nimbus/assets/scene_queries.h"

namespace nimbus::render {

struct LightView {
    glm::mat4 view{1.0f};            // origin-relative world → light view (light looks down −Z)
    glm::mat4 viewProjection{1.0f};  // origin-relative world → clip (reversed Z, [0,1] depth)
    bool perspective = false;
    float depthNear = 0.0f;          // view depth range the projection covers
    float depthFar = 1.0f;
    glm::vec2 halfExtent{1.0f};      // orthographic half size in metres; perspective: tan of half angles
};

// Views covering `bounds` (world space) as seen from the light. `origin` is View::origin.
std::vector<LightView> makeLightViews(const assets::ResolvedLight& light, const assets::Aabb& bounds,
                                      const glm::dvec3& origin);

// Light-space depth of an origin-relative point (distance along the light view's −Z).
inline float lightViewDepth(const LightView& v, const glm::vec3& p) { return -(v.view * glm::vec4(p, 1.0f)).z; }

// The cube face (0..5: +X −X +Y −Y +Z −Z) a direction from a point light falls in; matches the
// order of makeLightViews for point lights and the GLSL lookup.
int cubeFace(const glm::vec3& direction);

}  // namespace nimbus::render
