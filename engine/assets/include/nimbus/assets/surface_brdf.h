#pragma once
// glTF 2.0's metallic-roughness BRDF (the glTF specification, appendix B): the ONE CPU definition,
// used by the reference renderer; shaders/common/surface_brdf.glsl mirrors it formula for formula.
//
//   c_diff = baseColor · (1 − metallic),  f0 = mix(0.04, baseColor, metallic),  α = roughness²
//   F   = f0 + (1 − f0)(1 − v·h)⁵                                   (Schlick)
//   D   = α² χ⁺(n·h) / (π ((n·h)²(α² − 1) + 1)²)                    (Trowbridge–Reitz / GGX)
//   Vis = 1 / ((|n·l| + √(α² + (1 − α²)(n·l)²)) (|n·v| + √(α² + (1 − α²)(n·v)²)))
//                                                                    (separable Smith, G / (4 |n·l| |n·v|))
//   f   = (1 − F) c_diff / π + F · D · Vis
//
// Roughness below kMinRoughness is taken as kMinRoughness: a punctual light's highlight on a perfect
// mirror is a delta, which neither renderer can show.
//
// Does not: apply the light's irradiance or any visibility (light_model.h, the renderers do).
#include <glm/glm.hpp>

namespace nimbus::assets {

inline constexpr double kMinRoughness = 0.03;

struct SurfaceBrdf {
    glm::dvec3 diffuse{0.0};  // c_diff / π
    glm::dvec3 f0{0.04};
    double alpha2 = 1.0;      // α²
};

SurfaceBrdf surfaceBrdf(const glm::dvec3& baseColor, double metallic, double roughness);

// f(l, v) · (n·l) for unit n, v (towards the viewer) and l (towards the light) with nl = n·l > 0.
glm::dvec3 brdfTimesCosine(const SurfaceBrdf& brdf, const glm::dvec3& n, const glm::dvec3& v, const glm::dvec3& l, double nl);

}  // namespace nimbus::assets
