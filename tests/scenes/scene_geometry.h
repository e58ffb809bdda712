#pragma once
// Test helpers for scene-based tests: meshes built in memory, the pixel rays of render/view.h, ray
// tests against boxes and planes, and the 2D convex hull of projected points. Everything here is
// computed from geometry alone, never from a rendered image.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "nimbus/assets/scene.h"
#include "nimbus/assets/scene_queries.h"
#include "nimbus/render/view.h"

namespace nimbus::test {

// corner, corner+u, corner+u+v, corner+v as two counter-clockwise triangles facing cross(u, v).
inline assets::Primitive quad(const glm::vec3& corner, const glm::vec3& u, const glm::vec3& v, int material) {
    assets::Primitive p;
    const glm::vec3 n = glm::normalize(glm::cross(u, v));
    p.positions = {corner, corner + u, corner + u + v, corner + v};
    p.normals = {n, n, n, n};
    p.indices = {0, 1, 2, 0, 2, 3};
    p.material = material;
    p.boundsMin = glm::min(glm::min(p.positions[0], p.positions[1]), glm::min(p.positions[2], p.positions[3]));
    p.boundsMax = glm::max(glm::max(p.positions[0], p.positions[1]), glm::max(p.positions[2], p.positions[3]));
    return p;
}

// An axis-aligned box with outward faces and flat normals, as one primitive.
inline assets::Primitive box(const glm::vec3& lo, const glm::vec3& hi, int material) {
    const glm::vec3 d = hi - lo;
    const assets::Primitive faces[6] = {
        quad({lo.x, lo.y, lo.z}, {0, 0, d.z}, {0, d.y, 0}, material), quad({hi.x, lo.y, lo.z}, {0, d.y, 0}, {0, 0, d.z}, material),
        quad({lo.x, lo.y, lo.z}, {d.x, 0, 0}, {0, 0, d.z}, material), quad({lo.x, hi.y, lo.z}, {0, 0, d.z}, {d.x, 0, 0}, material),
        quad({lo.x, lo.y, lo.z}, {0, d.y, 0}, {d.x, 0, 0}, material), quad({lo.x, lo.y, hi.z}, {d.x, 0, 0}, {0, d.y, 0}, material)};
    assets::Primitive out;
    for (const assets::Primitive& f : faces) {
        const auto base = static_cast<std::uint32_t>(out.positions.size());
        out.positions.insert(out.positions.end(), f.positions.begin(), f.positions.end());
        out.normals.insert(out.normals.end(), f.normals.begin(), f.normals.end());
        for (const std::uint32_t i : f.indices) out.indices.push_back(base + i);
    }
    out.material = material;
    out.boundsMin = lo;
    out.boundsMax = hi;
    return out;
}

// The unit direction through the centre of pixel (x, y) (row 0 at the top), render/view.h's formula.
inline glm::dvec3 pixelRay(const render::View& v, int x, int y) {
    const double t = v.tanHalfFovY;
    const double a = static_cast<double>(v.width) / v.height;
    return glm::normalize(v.forward + v.right * ((2.0 * (x + 0.5) / v.width - 1.0) * t * a) +
                          v.up * ((1.0 - 2.0 * (y + 0.5) / v.height) * t));
}

// Entry distance of the ray into the box (slab test), if it enters at t > 0.
inline std::optional<double> hitBox(const glm::dvec3& origin, const glm::dvec3& dir, const assets::Aabb& b) {
    double t0 = 0.0, t1 = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 3; ++i) {
        if (std::abs(dir[i]) < 1e-300) {
            if (origin[i] < b.min[i] || origin[i] > b.max[i]) return std::nullopt;
            continue;
        }
        double a = (b.min[i] - origin[i]) / dir[i], c = (b.max[i] - origin[i]) / dir[i];
        if (a > c) std::swap(a, c);
        t0 = std::max(t0, a);
        t1 = std::min(t1, c);
    }
    if (t0 > t1) return std::nullopt;
    return t0;
}

// Distance along the ray to the plane y = height, if it is hit in front.
inline std::optional<double> hitGround(const glm::dvec3& origin, const glm::dvec3& dir, double height) {
    if (std::abs(dir.y) < 1e-12) return std::nullopt;
    const double t = (height - origin.y) / dir.y;
    if (!(t > 0.0)) return std::nullopt;
    return t;
}

// Pixel-space position (x right, y down, pixel centres at +0.5) of a world point under viewProjection.
inline glm::dvec2 projectToImage(const render::View& v, const glm::dvec3& world) {
    const glm::dvec4 clip = glm::dmat4(v.viewProjection) * glm::dvec4(glm::dvec3(v.toRelative(world)), 1.0);
    return {(clip.x / clip.w + 1.0) * 0.5 * v.width, (1.0 - clip.y / clip.w) * 0.5 * v.height};
}

inline std::array<glm::dvec3, 8> corners(const glm::dvec3& lo, const glm::dvec3& hi, const glm::dmat4& world) {
    std::array<glm::dvec3, 8> out;
    for (int i = 0; i < 8; ++i)
        out[static_cast<std::size_t>(i)] =
            glm::dvec3(world * glm::dvec4(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z, 1.0));
    return out;
}

// The convex hull of points in the image plane, with a signed distance to its boundary.
class ConvexHull {
public:
    explicit ConvexHull(std::vector<glm::dvec2> points) {
        std::sort(points.begin(), points.end(), [](const glm::dvec2& a, const glm::dvec2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
        auto cross = [](const glm::dvec2& o, const glm::dvec2& a, const glm::dvec2& b) {
            return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
        };
        std::vector<glm::dvec2> h(2 * points.size());
        std::size_t k = 0;
        for (const auto& p : points) {  // Andrew's monotone chain
            while (k >= 2 && cross(h[k - 2], h[k - 1], p) <= 0) --k;
            h[k++] = p;
        }
        for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
            while (k >= lower && cross(h[k - 2], h[k - 1], points[i]) <= 0) --k;
            h[k++] = points[i];
        }
        h.resize(k > 1 ? k - 1 : k);
        vertices_ = h;
    }

    const std::vector<glm::dvec2>& vertices() const { return vertices_; }

    // Signed distance: negative inside, positive outside (exact for points near an edge).
    double signedDistance(const glm::dvec2& p) const {
        double inside = -std::numeric_limits<double>::infinity();
        double nearest = std::numeric_limits<double>::infinity();
        for (std::size_t i = 0; i < vertices_.size(); ++i) {
            const glm::dvec2 a = vertices_[i], b = vertices_[(i + 1) % vertices_.size()];
            const glm::dvec2 e = b - a;
            const glm::dvec2 outward = glm::normalize(glm::dvec2(e.y, -e.x));  // the chain above runs counter-clockwise in (x, y)
            inside = std::max(inside, glm::dot(p - a, outward));
            const double s = std::clamp(glm::dot(p - a, e) / glm::dot(e, e), 0.0, 1.0);
            nearest = std::min(nearest, glm::length(p - (a + s * e)));
        }
        return inside <= 0.0 ? inside : nearest;
    }

private:
    std::vector<glm::dvec2> vertices_;
};

}  // namespace nimbus::test
