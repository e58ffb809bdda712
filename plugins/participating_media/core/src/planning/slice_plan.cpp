#include "nimbus/media/slice_plan.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "nimbus/media/optics.h"

namespace nimbus::media {
namespace {

constexpr int kGrid = 32;

// The cell of the light's 32x32 column grid that a texture coordinate falls in, edges included; a
// particle far outside the view (or at a non-finite coordinate) counts in the nearest edge cell.
int gridCell(double u) {
    if (!(u > 0.0)) return 0;
    return u >= 1.0 ? kGrid - 1 : static_cast<int>(u * kGrid);
}

}  // namespace

SliceEstimate estimateSlices(const ParticleSet& particles, const gpu::LightView& view, const glm::dvec3& origin) {
    SliceEstimate e;
    if (particles.empty()) return e;
    std::vector<double> column(kGrid * kGrid, 0.0);
    const glm::dmat4 viewMatrix(view.view);
    const glm::dmat4 projection = glm::dmat4(view.viewProjection) * glm::inverse(viewMatrix);
    double nearest = std::numeric_limits<double>::infinity(), farthest = -nearest, radiusSum = 0.0;
    double densest = 0.0;  // max over particles of √τ_p / R_p (τ_p: its peak column)
    std::vector<double> spans;
    spans.reserve(particles.size());
    // Peak column of one particle through its centre: σ ∫ e^{−k u²} du over the chord ≈ 0.8355·σR.
    const double columnPerSigmaRadius = std::sqrt(kPi / kKernelFalloff) * std::erf(std::sqrt(kKernelFalloff));
    for (std::size_t i = 0; i < particles.size(); ++i) {
        const glm::dvec4 v = viewMatrix * glm::dvec4(particles.position[i] - origin, 1.0);
        const double r = particles.radius[i];
        const double depth = -v.z;  // slice planes are planes of constant view depth
        nearest = std::min(nearest, depth - r);
        farthest = std::max(farthest, depth + r);
        radiusSum += r;
        if (!view.perspective) spans.push_back(r);
        else if (depth > 0.0) spans.push_back(r / std::max(glm::length(glm::dvec3(v)), r));
        if (r > 0.0) densest = std::max(densest, std::sqrt(columnPerSigmaRadius * particles.sigma[i] * r) / r);
        const glm::dvec4 clip = projection * v;
        if (clip.w <= 0.0) continue;
        const glm::dvec2 uv = (glm::dvec2(clip) / clip.w) * 0.5 + 0.5;
        const int x = gridCell(uv.x), y = gridCell(uv.y);
        column[static_cast<std::size_t>(y * kGrid + x)] += columnPerSigmaRadius * particles.sigma[i] * r;
    }
    e.depthNear = std::max(nearest, static_cast<double>(view.depthNear));
    e.depthFar = std::max(farthest, e.depthNear + 1e-6);
    e.depthExtent = e.depthFar - e.depthNear;
    e.meanRadius = radiusSum / static_cast<double>(particles.size());
    if (!spans.empty()) {
        std::nth_element(spans.begin(), spans.begin() + static_cast<std::ptrdiff_t>(spans.size() / 2), spans.end());
        e.medianSpan = spans[spans.size() / 2];
    }
    e.columnDepth = *std::max_element(column.begin(), column.end());
    double wanted = std::max(e.meanRadius > 0.0 ? e.depthExtent / e.meanRadius : 0.0, 2.0 * e.columnDepth);
    // Linear interpolation of one particle's τ_p·Φ(x/s) (s = R/3) across a spacing h errs by up to
    // h²/8 · τ_p·φ(1)/s² ≈ 0.27·τ_p·(h/R)². Keeping that under 0.02 (2% in transmittance) needs
    // h ≤ 0.27·R/√τ_p (docs/design-notes.md).
    wanted = std::max(wanted, e.depthExtent * densest / 0.27);
    // A point or spot light among the particles (some reach behind its near plane): the medium
    // nearest the lamp, where 1/d² weights its transmittance most, is seen through the first slices,
    // and linear interpolation across a slice one radius deep misses how τ grows there. Half the
    // spacing (docs/design-notes.md).
    if (view.perspective && nearest <= static_cast<double>(view.depthNear)) wanted *= 2.0;
    // A medium whose extent overflows the light's view (radii near the float limit) has no finite
    // estimate: it gets the most slices.
    if (!(wanted <= static_cast<double>(kMaxSlices))) wanted = kMaxSlices;
    const int rounded = 4 * static_cast<int>(std::ceil(std::min(wanted, static_cast<double>(kMaxSlices)) / 4.0));
    e.slices = std::clamp(rounded, kMinSlices, kMaxSlices);
    return e;
}

SliceEstimate estimateSlices(const ParticleSet& particles, const std::vector<Volume>& volumes, const gpu::LightView& view,
                             const glm::dvec3& origin) {
    SliceEstimate e = estimateSlices(particles, view, origin);
    if (volumes.empty()) return e;
    const glm::dmat4 viewMatrix(view.view);
    double nearest = std::numeric_limits<double>::infinity(), farthest = -nearest, column = 0.0;
    for (const Volume& v : volumes) {
        const Aabb box = volumeBounds(v);
        for (int c = 0; c < 8; ++c) {
            const glm::dvec3 corner(c & 1 ? box.max.x : box.min.x, c & 2 ? box.max.y : box.min.y, c & 4 ? box.max.z : box.min.z);
            const double depth = -(viewMatrix * glm::dvec4(corner - origin, 1.0)).z;
            nearest = std::min(nearest, depth);
            farthest = std::max(farthest, depth);
        }
        column = std::max(column, v.sigma() * glm::length(box.max - box.min));
    }
    const double spacing = particles.empty() ? 0.0 : e.depthExtent / e.slices;
    if (!particles.empty()) {
        nearest = std::min(nearest, e.depthNear);
        farthest = std::max(farthest, e.depthFar);
    }
    e.depthNear = std::max(nearest, static_cast<double>(view.depthNear));
    e.depthFar = std::max(farthest, e.depthNear + 1e-6);
    e.depthExtent = e.depthFar - e.depthNear;
    e.columnDepth = std::max(e.columnDepth, column);
    // Inside a constant volume τ grows linearly, which the slices interpolate exactly; its faces
    // and its column's size set the spacing as a particle's would.
    double wanted = std::max(spacing > 0.0 ? e.depthExtent / spacing : 0.0, 2.0 * e.columnDepth);
    const int rounded = 4 * static_cast<int>(std::ceil(std::min(wanted, static_cast<double>(kMaxSlices)) / 4.0));
    e.slices = std::clamp(rounded, kMinSlices, kMaxSlices);
    return e;
}

int sliceResolutionFor(const SliceEstimate& estimate, const gpu::LightView& view, double texelsPerRadius, int minimum) {
    constexpr int kMax = 256;
    if (!(estimate.medianSpan > 0.0)) return kMax;
    // The view spans 2·halfExtent (metres, or tan of the half angle) over its texels.
    const double wanted = 2.0 * static_cast<double>(std::max(view.halfExtent.x, view.halfExtent.y)) * texelsPerRadius / estimate.medianSpan;
    const int rounded = 16 * static_cast<int>(std::ceil(std::min(wanted, static_cast<double>(kMax)) / 16.0));
    return std::clamp(rounded, minimum, kMax);
}

SlabRange particleSlabs(double depth, double radius, bool perspective, double depthNear, double depthFar, int slices) {
    if (perspective && depth + radius <= 0.0) return {};  // wholly behind the light
    const double spacing = (depthFar - depthNear) / slices;
    auto slab = [&](double d) { return std::clamp(static_cast<int>(std::floor((d - depthNear) / spacing)), 0, slices - 1); };
    return {slab(depth - radius), slab(depth + radius)};
}

void appendSlabPieces(const ParticleSet& particles, const gpu::LightView& view, const glm::dvec3& origin, int slices,
                      std::vector<std::uint32_t>& pieces, int firstSlab) {
    const glm::dmat4 viewMatrix(view.view);
    const glm::dvec2 half(view.halfExtent);
    for (std::size_t i = 0; i < particles.size(); ++i) {
        const glm::dvec3 p(viewMatrix * glm::dvec4(particles.position[i] - origin, 1.0));
        // An orthographic view may be a crop of the medium (slice_crop.h): only what reaches it.
        if (!view.perspective && (std::abs(p.x) > half.x + particles.radius[i] || std::abs(p.y) > half.y + particles.radius[i])) continue;
        const double depth = -p.z;
        const SlabRange range = particleSlabs(depth, particles.radius[i], view.perspective, view.depthNear, view.depthFar, slices);
        for (int k = std::max(range.first, firstSlab); k <= range.last; ++k)
            pieces.push_back(static_cast<std::uint32_t>(i) << kSlabBits | static_cast<std::uint32_t>(k));
    }
}

}  // namespace nimbus::media
