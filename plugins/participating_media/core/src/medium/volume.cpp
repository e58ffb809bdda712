#include "nimbus/media/volume.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace nimbus::media {

Volume makeVolume(VolumeShape shape, const glm::dmat4& world, const glm::dvec3& size, const Medium& medium) {
    return {shape, world, glm::inverse(world), size, medium, {}};
}

Volume makeVolume(const VolumeDesc& desc, const glm::dmat4& world, const Medium& medium, std::string origin) {
    Volume v = makeVolume(desc.shape, world, desc.size, medium);
    v.origin = std::move(origin);
    return v;
}

VolumeChord volumeChord(const Volume& v, const glm::dvec3& origin, const glm::dvec3& dir) {
    // In the node's frame the parameter t is the world's (an affine map keeps it), with the
    // extents scaled to a unit cube or sphere.
    const glm::dvec3 half = 0.5 * v.size;
    const glm::dvec3 o = glm::dvec3(v.toLocal * glm::dvec4(origin, 1.0)) / half;
    const glm::dvec3 d = glm::dmat3(v.toLocal) * dir / half;
    VolumeChord c;
    if (v.shape == VolumeShape::Ellipsoid) {
        // |o + t d|² = 1, in the form that does not cancel when the ray passes far off the centre.
        const double a = glm::dot(d, d);
        if (!(a > 0.0)) return c;
        const double tClosest = -glm::dot(o, d) / a;
        const glm::dvec3 perp = o + tClosest * d;
        const double b2 = glm::dot(perp, perp);
        if (!(b2 < 1.0)) return c;
        const double h = std::sqrt((1.0 - b2) / a);
        return {tClosest - h, tClosest + h};
    }
    c.enter = -std::numeric_limits<double>::infinity();
    c.exit = std::numeric_limits<double>::infinity();
    for (int axis = 0; axis < 3; ++axis) {
        if (d[axis] == 0.0) {
            if (std::abs(o[axis]) > 1.0) return {1.0, 0.0};
            continue;
        }
        double t0 = (-1.0 - o[axis]) / d[axis], t1 = (1.0 - o[axis]) / d[axis];
        if (t0 > t1) std::swap(t0, t1);
        c.enter = std::max(c.enter, t0);
        c.exit = std::min(c.exit, t1);
    }
    return c.exit > c.enter ? c : VolumeChord{};
}

bool volumeContains(const Volume& v, const glm::dvec3& point) {
    const glm::dvec3 p = glm::dvec3(v.toLocal * glm::dvec4(point, 1.0)) / (0.5 * v.size);
    if (v.shape == VolumeShape::Ellipsoid) return glm::dot(p, p) < 1.0;
    return std::abs(p.x) < 1.0 && std::abs(p.y) < 1.0 && std::abs(p.z) < 1.0;
}

Aabb volumeBounds(const Volume& v) {
    // The node's box corners (an ellipsoid lies inside its box).
    Aabb bounds;
    const glm::dvec3 half = 0.5 * v.size;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::dvec3 local((corner & 1 ? 1.0 : -1.0) * half.x, (corner & 2 ? 1.0 : -1.0) * half.y, (corner & 4 ? 1.0 : -1.0) * half.z);
        bounds.extend(glm::dvec3(v.world * glm::dvec4(local, 1.0)));
    }
    return bounds;
}

Aabb volumeBounds(const std::vector<Volume>& volumes) {
    Aabb bounds;
    for (const Volume& v : volumes) bounds.extend(volumeBounds(v));
    return bounds;
}

}  // namespace nimbus::media
