#include "nimbus/assets/fog.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace nimbus::assets {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// ln((1 − e^(−x))/x), the height integral's shape: 0 at x = 0, stable on both sides.
double logShape(double x) {
    if (x == 0.0) return 0.0;
    if (x > 0.0) return std::log(-std::expm1(-x) / x);
    return -x + std::log(-std::expm1(x) / -x);  // x < 0: factor e^(−x) out so nothing overflows
}

}  // namespace

double heightFogDepth(const Fog& fog, double originHeight, double dirY, double z) {
    if (!(fog.density > 0.0) || !(z > 0.0)) return 0.0;
    const double k = fog.falloff;
    if (k == 0.0) return fog.density * z;
    const double a = k * dirY;
    const double logScale = std::log(fog.density) - k * (originHeight - fog.base);
    double logDepth = 0.0;
    if (std::isinf(z)) {
        if (!(a > 0.0)) return kInfinity;  // level or downwards: the fog never thins out
        logDepth = logScale - std::log(a);
    } else {
        logDepth = logScale + std::log(z) + logShape(a * z);
    }
    return logDepth > 700.0 ? kInfinity : std::exp(logDepth);
}

double fogFactor(const Fog& fog, double originHeight, double dirY, double z) {
    switch (fog.mode) {
        case FogMode::None: return 1.0;
        case FogMode::Exp: return fog.density > 0.0 ? std::exp(-fog.density * std::max(z, 0.0)) : 1.0;
        case FogMode::Exp2: {
            const double x = fog.density > 0.0 ? fog.density * std::max(z, 0.0) : 0.0;
            return std::exp(-x * x);
        }
        case FogMode::Linear:
            if (std::isinf(z)) return 0.0;
            return std::clamp((fog.end - z) / (fog.end - fog.start), 0.0, 1.0);
        case FogMode::Height: return std::exp(-heightFogDepth(fog, originHeight, dirY, z));
    }
    return 1.0;
}

double fogBackgroundDistance(const Fog& fog, double zfar) {
    if (fog.hasEnd) return fog.end;
    return zfar > 0.0 ? zfar : kInfinity;
}

glm::dvec3 applyFog(const Fog& fog, double f, const glm::dvec3& radiance) { return f * radiance + (1.0 - f) * fog.color; }

}  // namespace nimbus::assets
