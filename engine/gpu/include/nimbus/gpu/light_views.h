#pragma once
// Punctual lights as shaders see them, and views from a light: used for mesh shadow maps and, by
// the media plugin, for transmittance slices. A directional light gets one orthographic view fitted
// around the bounds it must cover, a spot light one perspective view along its axis, a point light
// six 90° cube-face views. All matrices map origin-relative world positions (see View).
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "nimbus/base/aabb.h"

namespace nimbus::gpu {

enum class LightKind : std::uint8_t { Directional, Point, Spot };

// A KHR_lights_punctual light resolved to world space.
struct PunctualLight {
    LightKind kind = LightKind::Directional;
    glm::dvec3 position{0.0};
    glm::dvec3 direction{0.0, 0.0, -1.0};  // unit; the direction light travels (directional, spot)
    glm::vec3 radiance{1.0f};              // colour × intensity (lux for directional, candela otherwise)
    double range = 0.0;                    // 0: infinite
    double innerConeAngle = 0.0;           // spot, radians
    double outerConeAngle = 0.7853981633974483;
};

struct LightView {
    glm::mat4 view{1.0f};            // origin-relative world → light view (light looks down −Z)
    glm::mat4 viewProjection{1.0f};  // origin-relative world → clip (reversed Z, [0,1] depth)
    bool perspective = false;
    float depthNear = 0.0f;          // view depth range the projection covers
    float depthFar = 1.0f;
    glm::vec2 halfExtent{1.0f};      // orthographic half size in metres; perspective: tan of half angles
};

// Views covering `bounds` (world space) as seen from the light. `origin` is View::origin.
std::vector<LightView> makeLightViews(const PunctualLight& light, const Aabb& bounds, const glm::dvec3& origin);

// Light-space depth of an origin-relative point (distance along the light view's −Z).
inline float lightViewDepth(const LightView& v, const glm::vec3& p) { return -(v.view * glm::vec4(p, 1.0f)).z; }

// The cube face (0..5: +X −X +Y −Y +Z −Z) a direction from a point light falls in; matches the
// order of makeLightViews for point lights and the GLSL lookup.
int cubeFace(const glm::vec3& direction);

// A direction from a point light in the view of its cube face `face`: x and y across the face (its
// NDC is xy / z) and z the view depth. The faces are OpenGL's cube-map faces, so this is a signed
// swizzle, mirrored by the GLSL cubeFaceView: the shaders need no face's matrices.
glm::vec3 cubeFaceView(int face, const glm::vec3& direction);

// Whether view `v` looks along cube face `face` as makeLightViews' faces do (its rotation is
// cubeFaceView's swizzle): the shaders read a six-view light's faces so, not by their matrices.
bool isCubeFaceView(int face, const LightView& v);

}  // namespace nimbus::gpu
