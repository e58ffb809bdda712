#include "nimbus/assets/surface_brdf.h"

#include <algorithm>
#include <cmath>

namespace nimbus::assets {
namespace {
constexpr double kPi = 3.14159265358979323846;
}

SurfaceBrdf surfaceBrdf(const glm::dvec3& baseColor, double metallic, double roughness) {
    const double r = std::max(roughness, kMinRoughness);
    const double alpha = r * r;
    return {baseColor * ((1.0 - metallic) / kPi), glm::mix(glm::dvec3(0.04), baseColor, metallic), alpha * alpha};
}

glm::dvec3 brdfTimesCosine(const SurfaceBrdf& brdf, const glm::dvec3& n, const glm::dvec3& v, const glm::dvec3& l, double nl) {
    glm::dvec3 h = l + v;
    h /= std::sqrt(std::max(glm::dot(h, h), 1e-24));  // l = −v (grazing from behind) gives h = 0: no NaN
    const double vh = std::clamp(glm::dot(v, h), 0.0, 1.0);
    const double nh = glm::dot(n, h);
    const double nv = std::abs(glm::dot(n, v));
    const double m = 1.0 - vh, m2 = m * m;
    const glm::dvec3 fresnel = brdf.f0 + (1.0 - brdf.f0) * (m2 * m2 * m);
    const double a2 = brdf.alpha2;
    const double d = nh * nh * (a2 - 1.0) + 1.0;
    const double distribution = nh > 0.0 ? a2 / (kPi * d * d) : 0.0;
    const double visibility = 1.0 / ((nl + std::sqrt(a2 + (1.0 - a2) * nl * nl)) * (nv + std::sqrt(a2 + (1.0 - a2) * nv * nv)));
    return ((1.0 - fresnel) * brdf.diffuse + fresnel * (distribution * visibility)) * nl;
}

}  // namespace nimbus::assets
