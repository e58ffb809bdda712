#pragma once
// How much light from one KHR_lights_punctual light arrives at a point: the ONE CPU definition,
// used by the reference renderer; the GPU shaders must mirror these formulas exactly.
//
// Directional: E = color · intensity (lux), arriving from -direction.
// Point / spot: E = color · intensity / d² (candela at distance d) × the range window
//   clamp(1 − (d / range)⁴, 0, 1)² when a range is given (the glTF recommendation), 1 otherwise.
// Spot, additionally: × a², a = clamp(cos θ · scale + offset, 0, 1) with
//   scale = 1 / max(0.001, cos(inner) − cos(outer)), offset = −cos(outer) · scale
//   (KHR_lights_punctual reference), θ the angle between the spot direction and the point.
//
// Does not: apply visibility (mesh shadows, medium transmittance) or the surface cosine.
#include <glm/glm.hpp>

#include "nimbus/assets/scene_queries.h"

namespace nimbus::assets {

struct LightSample {
    glm::dvec3 toLight{0.0, 1.0, 0.0};  // unit vector from the point towards the light
    double distance = 0.0;              // +infinity for directional lights
    glm::dvec3 irradiance{0.0};         // E on a surface facing the light, before visibility
};

// A point closer than 1e-9 to a point or spot light gets zero irradiance (never Inf or NaN).
LightSample sampleLight(const ResolvedLight& light, const glm::dvec3& point);

// The range window alone: clamp(1 − (d / range)⁴, 0, 1)², 1 for range <= 0 (infinite).
double rangeWindow(double distance, double range);

// The spot cone factor alone (a² above) for cos θ = cosAngle.
double spotAttenuation(double cosAngle, double innerConeAngle, double outerConeAngle);

}  // namespace nimbus::assets
