#include "nimbus/media/volume.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace nimbus::media {

Volume makeVolume(VolumeShape shape, const glm::dmat4& world, const glm::dvec3& size, const Medium& medium) {
    Volume v;
    v.shape = shape;
    v.world = world;
    v.toLocal = glm::inverse(world);
    v.size = size;
    v.medium = medium;
    return v;
}

Volume makeVolume(const VolumeDesc& desc, const glm::dmat4& world, const Medium& medium, std::string origin, double time) {
    Volume v = makeVolume(desc.shape, world, desc.size, medium);
    v.origin = std::move(origin);
    if (desc.noise) {
        v.noise = desc.noise;
        v.noiseParams = noiseParams(*desc.noise, desc.shape == VolumeShape::Ellipsoid);
        v.drift = desc.noise->velocity * time;
    }
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

NoisePoint noisePoint(const Volume& v, const glm::dvec3& point) {
    const glm::dvec3 local(v.toLocal * glm::dvec4(point, 1.0));
    const double frequency = v.noise ? v.noise->frequency : 1.0;
    return {glm::vec3((local - v.drift) * frequency), glm::vec3(local / (0.5 * v.size))};
}

double volumeExtinction(const Volume& v, const glm::dvec3& point) {
    if (!volumeContains(v, point)) return 0.0;
    if (!v.noise) return v.sigma();
    const NoisePoint n = noisePoint(v, point);
    return v.sigma() * static_cast<double>(noiseDensity(v.noiseParams, n.p, n.unit, v.shape == VolumeShape::Ellipsoid));
}

namespace {

// ∫ σ over [a, b] by adaptive Simpson: `fa`, `fm`, `fb` the integrand at a, the middle and b,
// `whole` Simpson's rule over [a, b]. Richardson's correction on the accepted halves.
template <typename F>
double adaptiveSimpson(const F& f, double a, double b, double fa, double fm, double fb, double whole, double tolerance, int depth) {
    const double m = 0.5 * (a + b), lm = 0.5 * (a + m), rm = 0.5 * (m + b);
    const double flm = f(lm), frm = f(rm);
    const double left = (m - a) / 6.0 * (fa + 4.0 * flm + fm), right = (b - m) / 6.0 * (fm + 4.0 * frm + fb);
    const double change = left + right - whole;
    if (depth <= 0 || std::abs(change) <= 15.0 * (tolerance * std::abs(left + right) + 1e-12)) return left + right + change / 15.0;
    return adaptiveSimpson(f, a, m, fa, flm, fm, left, tolerance, depth - 1) + adaptiveSimpson(f, m, b, fm, frm, fb, right, tolerance, depth - 1);
}

}  // namespace

int volumeQuadratureIntervals(const Volume& v, const glm::dvec3& dir, double length) {
    if (!v.noise) return 1;
    // Four intervals per cycle of the finest octave along the chord (sines run up to 1.5× faster).
    const double cycles = glm::length(glm::dmat3(v.toLocal) * dir) * length * v.noise->frequency * std::ldexp(1.5, v.noise->octaves - 1);
    return static_cast<int>(std::clamp(std::ceil(4.0 * cycles), 1.0, 65536.0));
}

double volumeOpticalDepth(const Volume& v, const glm::dvec3& origin, const glm::dvec3& dir, double t0, double t1, double tolerance) {
    const VolumeChord chord = volumeChord(v, origin, dir);
    const double a = std::max(t0, chord.enter), b = std::min(t1, chord.exit);
    if (!chord.hit() || !(b > a)) return 0.0;
    if (!v.noise) return v.sigma() * (b - a);
    const int intervals = volumeQuadratureIntervals(v, dir, b - a);
    const auto sigma = [&](double t) { return volumeExtinction(v, origin + t * dir); };
    const double h = (b - a) / intervals;
    double tau = 0.0, fa = sigma(a);
    for (int i = 0; i < intervals; ++i) {
        const double lo = a + i * h, hi = i + 1 == intervals ? b : lo + h, m = 0.5 * (lo + hi);
        const double fm = sigma(m), fb = sigma(hi);
        tau += adaptiveSimpson(sigma, lo, hi, fa, fm, fb, (hi - lo) / 6.0 * (fa + 4.0 * fm + fb), tolerance, 24);
        fa = fb;
    }
    return tau;
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
