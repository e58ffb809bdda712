#include "animation_sampling.h"

#include <algorithm>
#include <cmath>

namespace nimbus::assets {
namespace {

glm::dvec4 normalizedOrIdentity(const glm::dvec4& q) {
    const double length = glm::length(q);
    return length > 1e-300 && std::isfinite(length) ? q / length : glm::dvec4(0.0, 0.0, 0.0, 1.0);
}

}  // namespace

glm::dvec4 slerpShortest(const glm::dvec4& a, const glm::dvec4& b, double s) {
    const glm::dvec4 qa = normalizedOrIdentity(a);
    glm::dvec4 qb = normalizedOrIdentity(b);
    double d = glm::dot(qa, qb);
    if (d < 0.0) {  // q and -q are the same rotation: take the short way round
        qb = -qb;
        d = -d;
    }
    if (d > 0.9995) return normalizedOrIdentity(glm::mix(qa, qb, s));  // nearly equal: acos is ill-conditioned
    const double theta = std::acos(std::min(d, 1.0));
    const double sinTheta = std::sin(theta);
    return normalizedOrIdentity((std::sin((1.0 - s) * theta) * qa + std::sin(s * theta) * qb) / sinTheta);
}

glm::dvec4 sampleChannel(const AnimationChannel& channel, double t) {
    const std::size_t keys = channel.times.size();
    const bool cubic = channel.interpolation == Interpolation::CubicSpline;
    const bool rotation = channel.path == AnimationPath::Rotation;
    const std::size_t needed = cubic ? 3 * keys : keys;
    if (keys == 0 || channel.values.size() < needed)
        return rotation ? glm::dvec4(0.0, 0.0, 0.0, 1.0) : glm::dvec4(channel.path == AnimationPath::Scale ? 1.0 : 0.0);

    auto value = [&](std::size_t k) { return glm::dvec4(channel.values[cubic ? 3 * k + 1 : k]); };
    auto finish = [&](const glm::dvec4& v) { return rotation ? normalizedOrIdentity(v) : glm::dvec4(glm::dvec3(v), 0.0); };

    if (!(t > channel.times.front())) return finish(value(0));  // also catches NaN time
    if (t >= channel.times.back()) return finish(value(keys - 1));
    const auto upper = std::upper_bound(channel.times.begin(), channel.times.end(), t);
    const std::size_t k = static_cast<std::size_t>(upper - channel.times.begin()) - 1;
    const double t0 = channel.times[k];
    const double t1 = channel.times[k + 1];
    const double dt = t1 - t0;
    const double s = (t - t0) / dt;

    switch (channel.interpolation) {
        case Interpolation::Step: return finish(value(k));
        case Interpolation::Linear:
            return rotation ? slerpShortest(value(k), value(k + 1), s) : finish(glm::mix(value(k), value(k + 1), s));
        case Interpolation::CubicSpline: {
            const glm::dvec4 p0 = value(k);
            const glm::dvec4 m0 = dt * glm::dvec4(channel.values[3 * k + 2]);        // out-tangent of key k
            const glm::dvec4 p1 = value(k + 1);
            const glm::dvec4 m1 = dt * glm::dvec4(channel.values[3 * (k + 1)]);     // in-tangent of key k+1
            const double s2 = s * s, s3 = s2 * s;
            const glm::dvec4 v = (2 * s3 - 3 * s2 + 1) * p0 + (s3 - 2 * s2 + s) * m0 + (-2 * s3 + 3 * s2) * p1 + (s3 - s2) * m1;
            return finish(v);
        }
    }
    return finish(value(k));
}

}  // namespace nimbus::assets
