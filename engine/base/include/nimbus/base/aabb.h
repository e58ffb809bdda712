#pragma once
// An axis-aligned box in world space (double: scenes may lie far from the origin). Default: empty.
#include <limits>

#include <glm/glm.hpp>

namespace nimbus {

struct Aabb {
    glm::dvec3 min{std::numeric_limits<double>::infinity()};
    glm::dvec3 max{-std::numeric_limits<double>::infinity()};
    bool empty() const { return !(min.x <= max.x && min.y <= max.y && min.z <= max.z); }
    void extend(const glm::dvec3& p) { min = glm::min(min, p); max = glm::max(max, p); }
    void extend(const Aabb& b) { if (!b.empty()) { extend(b.min); extend(b.max); } }
    glm::dvec3 center() const { return 0.5 * (min + max); }
    glm::dvec3 extent() const { return max - min; }
    bool contains(const glm::dvec3& p) const { return glm::all(glm::greaterThanEqual(p, min)) && glm::all(glm::lessThanEqual(p, max)); }
};

}  // namespace nimbus
