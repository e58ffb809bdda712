#pragma once
// A bounding-volume hierarchy over particle spheres: "which particles does this ray segment cross?"
// and "which particles contain this point?" without scanning all N. Built once per frame from a
// ParticleSet; queries are const and safe from many threads at once.
//
// Deterministic: the build depends only on the input order and values, and a query visits particles
// in an order fixed by the tree and the ray, so sums over query results are the same bits every run.
//
// Does not: refit or update incrementally (rebuilding 10⁵ spheres takes milliseconds); store anything
// but positions and radii (callers index back into their ParticleSet).
#include <cmath>
#include <cstdint>
#include <utility>
#include <limits>
#include <vector>

#include <glm/glm.hpp>

#include "nimbus/media/particle_set.h"

namespace nimbus::media {

class ParticleBvh {
public:
    ParticleBvh() = default;
    explicit ParticleBvh(const ParticleSet& particles) { build(particles); }

    // Particles with radius <= 0 or sigma <= 0 are left out: they have no extinction.
    void build(const ParticleSet& particles);

    bool empty() const { return nodes_.empty(); }
    std::size_t particleCount() const { return spheres_.size(); }

    // Calls visit(particleIndex) for every particle whose open sphere meets the segment
    // origin + t·dir, t in [t0, t1] (dir unit length; t1 may be +inf). visit returns false to stop early.
    template <class Visit>
    void forEachOnSegment(const glm::dvec3& origin, const glm::dvec3& dir, double t0, double t1, Visit&& visit) const;

    // Calls visit(particleIndex) for every particle whose open sphere contains the point x.
    template <class Visit>
    void forEachContaining(const glm::dvec3& x, Visit&& visit) const;

    // Convenience: the indices, in visiting order.
    std::vector<std::uint32_t> particlesOnSegment(const glm::dvec3& origin, const glm::dvec3& dir, double t0,
                                                  double t1) const;
    std::vector<std::uint32_t> particlesContaining(const glm::dvec3& x) const;

    // World-space bounds of all spheres (empty bounds when there are none).
    glm::dvec3 boundsMin() const { return nodes_.empty() ? glm::dvec3(0.0) : nodes_[0].min; }
    glm::dvec3 boundsMax() const { return nodes_.empty() ? glm::dvec3(0.0) : nodes_[0].max; }

private:
    struct Node {
        glm::dvec3 min, max;
        std::uint32_t first = 0;  // leaf: first sphere slot; inner: index of the left child (right = left + 1)
        std::uint32_t count = 0;  // leaf: number of spheres; inner: 0
        std::uint8_t axis = 0;    // inner: split axis, to visit the nearer child first
    };
    struct Sphere {
        glm::dvec3 centre;
        double radius2;
        std::uint32_t particle;
    };

    std::vector<Node> nodes_;
    std::vector<Sphere> spheres_;  // leaf order
};

// ---- implementation of the templates ----

template <class Visit>
void ParticleBvh::forEachOnSegment(const glm::dvec3& origin, const glm::dvec3& dir, double t0, double t1,
                                   Visit&& visit) const {
    if (nodes_.empty() || !(t1 >= t0)) return;
    const glm::dvec3 inv(1.0 / dir.x, 1.0 / dir.y, 1.0 / dir.z);  // ±inf for axis-parallel rays: slabs still work
    auto slab = [&](const Node& n) {
        double lo = t0, hi = t1;
        for (int a = 0; a < 3; ++a) {
            const double o = origin[a], d = inv[a];
            if (dir[a] == 0.0) {
                if (o < n.min[a] || o > n.max[a]) return false;
                continue;
            }
            double ta = (n.min[a] - o) * d, tb = (n.max[a] - o) * d;
            if (ta > tb) std::swap(ta, tb);
            lo = ta > lo ? ta : lo;
            hi = tb < hi ? tb : hi;
            if (lo > hi) return false;
        }
        return true;
    };
    std::uint32_t stack[64];
    int top = 0;
    if (!slab(nodes_[0])) return;
    stack[top++] = 0;
    while (top > 0) {
        const Node& node = nodes_[stack[--top]];
        if (node.count > 0) {
            for (std::uint32_t s = node.first; s < node.first + node.count; ++s) {
                const Sphere& sp = spheres_[s];
                const glm::dvec3 v = sp.centre - origin;
                const double tc = glm::dot(v, dir);
                const glm::dvec3 perp = v - tc * dir;
                const double b2 = glm::dot(perp, perp);
                if (!(b2 < sp.radius2)) continue;
                const double h = std::sqrt(sp.radius2 - b2);
                if (tc + h <= t0 || tc - h >= t1) continue;
                if (!visit(sp.particle)) return;
            }
            continue;
        }
        const Node& left = nodes_[node.first];
        const Node& right = nodes_[node.first + 1];
        const bool hitL = slab(left), hitR = slab(right);
        // Push the farther child first so the nearer one is visited first (helps early exit).
        const bool leftFirst = dir[node.axis] >= 0.0;
        if (leftFirst) {
            if (hitR) stack[top++] = node.first + 1;
            if (hitL) stack[top++] = node.first;
        } else {
            if (hitL) stack[top++] = node.first;
            if (hitR) stack[top++] = node.first + 1;
        }
    }
}

template <class Visit>
void ParticleBvh::forEachContaining(const glm::dvec3& x, Visit&& visit) const {
    if (nodes_.empty()) return;
    std::uint32_t stack[64];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const Node& node = nodes_[stack[--top]];
        if (x.x < node.min.x || x.y < node.min.y || x.z < node.min.z || x.x > node.max.x || x.y > node.max.y ||
            x.z > node.max.z)
            continue;
        if (node.count > 0) {
            for (std::uint32_t s = node.first; s < node.first + node.count; ++s) {
                const glm::dvec3 v = x - spheres_[s].centre;
                if (glm::dot(v, v) < spheres_[s].radius2 && !visit(spheres_[s].particle)) return;
            }
            continue;
        }
        stack[top++] = node.first + 1;
        stack[top++] = node.first;
    }
}

}  // namespace nimbus::media
