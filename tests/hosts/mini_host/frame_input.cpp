#include "frame_input.h"

#include <limits>

namespace mini {
namespace {

void extendByBox(nimbus::Aabb& bounds, const glm::dmat4& world, const glm::vec3& lo, const glm::vec3& hi) {
    if (lo.x > hi.x) return;  // a mesh without triangles
    for (int i = 0; i < 8; ++i) {
        const glm::dvec3 corner(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z);
        bounds.extend(glm::dvec3(world * glm::dvec4(corner, 1.0)));
    }
}

}  // namespace

nimbus::Aabb instanceBounds(const Scene& scene, const std::vector<MeshInstance>& instances, BoxPer boxes) {
    nimbus::Aabb bounds;
    for (const MeshInstance& instance : instances) {
        glm::vec3 lo(std::numeric_limits<float>::infinity()), hi(-std::numeric_limits<float>::infinity());
        for (const Primitive& p : scene.meshes.at(static_cast<std::size_t>(instance.mesh)).primitives) {
            if (boxes == BoxPer::Primitive) extendByBox(bounds, instance.world, p.boundsMin, p.boundsMax);
            lo = glm::min(lo, p.boundsMin);
            hi = glm::max(hi, p.boundsMax);
        }
        if (boxes == BoxPer::Mesh) extendByBox(bounds, instance.world, lo, hi);
    }
    return bounds;
}

}  // namespace mini
