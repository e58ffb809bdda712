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

glm::mat4 standardProjection(const nimbus::gpu::View& v) {
    const double n = v.znear, f = v.zfar;
    glm::dmat4 p(0.0);
    if (v.orthographic) {  // depth = (z − n) / (f − n), z the view depth
        p[0][0] = 1.0 / v.orthoHalfExtent.x;
        p[1][1] = 1.0 / v.orthoHalfExtent.y;
        p[2][2] = -1.0 / (f - n);
        p[3][2] = -n / (f - n);
        p[3][3] = 1.0;
        return glm::mat4(p);
    }
    // depth = f (z − n) / ((f − n) z), or 1 − n/z without a far plane.
    const double t = v.tanHalfFovY;
    p[0][0] = 1.0 / (t * v.aspect);
    p[1][1] = 1.0 / t;
    p[2][2] = f > 0.0 ? -f / (f - n) : -1.0;
    p[2][3] = -1.0;
    p[3][2] = f > 0.0 ? -f * n / (f - n) : -n;
    return glm::mat4(p);
}

}  // namespace mini
