#include "planning/slice_crop.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "nimbus/gpu/view.h"
#include "nimbus/media/slice_plan.h"

namespace nimbus::media {

namespace {
// The meshes' overlap with the medium, grown by `margin` and kept inside it.
Aabb meshOverlap(const std::vector<OccluderBox>& meshes, const Aabb& medium, double margin) {
    Aabb region;
    for (const OccluderBox& box : meshes) {
        const glm::dvec3 half = axisAlignedHalf(box);
        const glm::dvec3 lo = glm::max(box.centre - half - margin, medium.min), hi = glm::min(box.centre + half + margin, medium.max);
        if (glm::any(glm::greaterThan(lo, hi))) continue;
        region.extend(lo);
        region.extend(hi);
    }
    return region;
}

// [lo, hi] widened about its middle to at least `least` half width, then moved inside [−limit, limit].
void widenInside(double& lo, double& hi, double least, double limit) {
    const double half = std::min(std::max(0.5 * (hi - lo), least), limit);
    const double mid = std::clamp(0.5 * (hi + lo), -limit + half, limit - half);
    lo = mid - half;
    hi = mid + half;
}
}  // namespace

std::optional<SliceCrop> meshCropView(const gpu::LightView& whole, int wholeSlices, const std::vector<OccluderBox>& meshes, const Aabb& medium,
                                      double margin, const glm::dvec3& origin) {
    if (whole.perspective || medium.empty() || wholeSlices <= 0) return std::nullopt;
    const Aabb region = meshOverlap(meshes, medium, margin);
    if (region.empty()) return std::nullopt;
    const glm::dmat4 view(whole.view);
    glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
    for (int c = 0; c < 8; ++c) {
        const glm::dvec3 corner(c & 1 ? region.max.x : region.min.x, c & 2 ? region.max.y : region.min.y, c & 4 ? region.max.z : region.min.z);
        const glm::dvec3 p(view * glm::dvec4(corner - origin, 1.0));
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    // The whole view is centred on its own footprint, which the crop stays inside.
    const glm::dvec2 wholeHalf(whole.halfExtent);
    const double wholeNear = static_cast<double>(whole.depthNear), wholeDepth = static_cast<double>(whole.depthFar) - wholeNear;
    const double depthFar = std::clamp(-lo.z, wholeNear + 1e-6, static_cast<double>(whole.depthFar));
    // Its first plane: a margin before the overlap, so a particle reaching a mesh lies wholly past it.
    const double first = std::clamp(-hi.z - margin, wholeNear, depthFar - 1e-6);
    const double across = std::min(wholeHalf.x / std::max(0.5 * (hi.x - lo.x), 1e-9), wholeHalf.y / std::max(0.5 * (hi.y - lo.y), 1e-9));
    if (across < kMinCropGain && wholeDepth < kMinCropGain * (depthFar - first)) return std::nullopt;
    widenInside(lo.x, hi.x, wholeHalf.x / kCropGain, wholeHalf.x);
    widenInside(lo.y, hi.y, wholeHalf.y / kCropGain, wholeHalf.y);
    const glm::dvec2 half(0.5 * (hi.x - lo.x), 0.5 * (hi.y - lo.y)), mid(0.5 * (hi.x + lo.x), 0.5 * (hi.y + lo.y));
    glm::dmat4 shift(1.0);
    shift[3][0] = -mid.x;
    shift[3][1] = -mid.y;
    // Planes kCropGain closer than the whole view's from `first` on, one more before it (its near
    // plane, whose zero no lookup reads), in fours as the slice layers hold them.
    const double planes = 1.0 + kCropGain * wholeSlices * (depthFar - first) / wholeDepth;
    SliceCrop crop{whole, std::clamp(4 * static_cast<int>(std::ceil(planes / 4.0 - 1e-9)), kMinSlices, kMaxSlices)};
    const double depthNear = first - (depthFar - first) / (crop.slices - 1);
    crop.view.view = glm::mat4(shift * view);
    crop.view.depthNear = static_cast<float>(depthNear);
    crop.view.depthFar = static_cast<float>(depthFar);
    crop.view.halfExtent = glm::vec2(half);
    crop.view.viewProjection = gpu::reversedOrthographic(half.x, half.y, depthNear, depthFar) * crop.view.view;
    return crop;
}

}  // namespace nimbus::media
