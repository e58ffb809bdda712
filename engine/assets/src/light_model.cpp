#include "nimbus/assets/light_model.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace nimbus::assets {

double rangeWindow(double distance, double range) {
    if (!(range > 0.0)) return 1.0;
    const double ratio = distance / range;
    const double ratio2 = ratio * ratio;
    const double window = std::clamp(1.0 - ratio2 * ratio2, 0.0, 1.0);
    return window * window;
}

double spotAttenuation(double cosAngle, double innerConeAngle, double outerConeAngle) {
    const double cosOuter = std::cos(outerConeAngle);
    const double scale = 1.0 / std::max(0.001, std::cos(innerConeAngle) - cosOuter);
    const double offset = -cosOuter * scale;
    const double a = std::clamp(cosAngle * scale + offset, 0.0, 1.0);
    return a * a;
}

LightSample sampleLight(const ResolvedLight& light, const glm::dvec3& point) {
    LightSample s;
    const glm::dvec3 radiance = glm::dvec3(light.params.color) * static_cast<double>(light.params.intensity);
    if (light.params.type == LightType::Directional) {
        s.toLight = -light.direction;
        s.distance = std::numeric_limits<double>::infinity();
        s.irradiance = radiance;
        return s;
    }
    const glm::dvec3 offset = light.position - point;
    const double d = glm::length(offset);
    s.distance = d;
    if (!(d >= 1e-9) || !std::isfinite(d)) return s;  // at the light: no direction, zero irradiance (toLight stays +Y)
    s.toLight = offset / d;
    double factor = rangeWindow(d, light.params.range) / (d * d);
    if (light.params.type == LightType::Spot)
        factor *= spotAttenuation(glm::dot(light.direction, -s.toLight), light.params.innerConeAngle, light.params.outerConeAngle);
    s.irradiance = radiance * factor;
    return s;
}

}  // namespace nimbus::assets
