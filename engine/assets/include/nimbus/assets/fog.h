#pragma once
// The fog factor f of a ray (scene-format.md §2.1): the ONE CPU definition, used by the reference
// renderer; shaders/common/fog.glsl mirrors it. z is the distance from the ray's origin along the
// unit direction, in metres, and may be +infinity.
//
//   exp     f = e^(−d·z)                 exp2   f = e^(−(d·z)²)
//   linear  f = clamp((e − z)/(e − s), 0, 1)
//   height  f = e^(−τ), τ = ∫0..z d·e^(−k·(y0 + t·dy − base)) dt = d·e^(−k·h)·z·(1 − e^(−a))/a,
//           h = y0 − base, a = k·dy·z; evaluated in log space (no overflow far below the base) with
//           expm1 (a → 0: the horizontal ray).
//
// Does not: know about meshes or media: callers pick z (a hit, the fog's end, the far plane).
#include "nimbus/assets/scene.h"

namespace nimbus::assets {

// `originHeight`: the world y of the ray's origin; `dirY`: the direction's y component.
double fogFactor(const Fog& fog, double originHeight, double dirY, double z);

// The optical depth τ of height fog (f = e^(−τ)); +infinity where it diverges.
double heightFogDepth(const Fog& fog, double originHeight, double dirY, double z);

// How far rays that hit nothing see fog: `end` when given, else the far plane (0: infinite).
double fogBackgroundDistance(const Fog& fog, double zfar);

// What is seen through the fog: f·radiance + (1 − f)·color.
glm::dvec3 applyFog(const Fog& fog, double f, const glm::dvec3& radiance);

}  // namespace nimbus::assets
