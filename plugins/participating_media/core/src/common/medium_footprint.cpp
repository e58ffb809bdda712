// The particles' footprint for the frame's planning (nimbus/media/medium_footprint.h).
#include "nimbus/media/medium_footprint.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace nimbus::media {

Aabb particleBounds(const ParticleSet& particles) {
    Aabb bounds;
    for (std::size_t i = 0; i < particles.size(); ++i) {
        const glm::dvec3 r(particles.radius[i]);
        bounds.extend(particles.position[i] - r);
        bounds.extend(particles.position[i] + r);
    }
    return bounds;
}

SplatFootprint splatFootprint(const ParticleSet& particles, const gpu::View& view, const std::vector<std::uint8_t>* which) {
    const double pixels = static_cast<double>(view.width) * view.height;
    const glm::dmat4 viewMatrix(view.view);
    // Pixels per metre at depth 1 (perspective) or per metre (orthographic), vertically.
    const double scale = view.height / (2.0 * (view.orthographic ? view.orthoHalfExtent.y : view.tanHalfFovY));
    double covered = 0.0, radiusTimesArea = 0.0;
    for (std::size_t i = 0; i < particles.size(); ++i) {
        if (which != nullptr && (i >= which->size() || (*which)[i] == 0)) continue;
        const glm::dvec3 c(viewMatrix * glm::dvec4(particles.position[i] - view.origin, 1.0));
        const double r = particles.radius[i], depth = -c.z;
        if (!view.orthographic && depth <= r) {
            covered += pixels;  // in front of or around the eye: a full-screen quad
            radiusTimesArea += pixels * std::sqrt(pixels);
            continue;
        }
        const double half = r * scale / (view.orthographic ? 1.0 : depth);  // the quad's half size in pixels
        const double area = std::min(4.0 * half * half, pixels);
        covered += area;
        radiusTimesArea += area * half;
    }
    return {covered / pixels, covered > 0.0 ? radiusTimesArea / covered : 0.0};
}

namespace {

// The interval of x/depth over a circle of radius r at (x, depth), depth > r: each end from the
// circle's nearest or farthest depth, whichever bounds it.
glm::dvec2 tangentInterval(double x, double depth, double r) {
    const double lo = x - r, hi = x + r;
    return {lo / (lo <= 0.0 ? depth - r : depth + r), hi / (hi >= 0.0 ? depth - r : depth + r)};
}

// Window pixels of an ndc interval pair, grown by margin and clipped to the view.
glm::ivec4 pixelRect(glm::dvec2 lo, glm::dvec2 hi, const gpu::View& view, int margin) {
    if (!(hi.x >= lo.x) || !(hi.y >= lo.y)) return glm::ivec4(0);
    const glm::dvec2 size(view.width, view.height);
    const glm::ivec2 a = glm::ivec2(glm::clamp(glm::floor((lo * 0.5 + 0.5) * size) - double(margin), glm::dvec2(0.0), size));
    const glm::ivec2 b = glm::ivec2(glm::clamp(glm::ceil((hi * 0.5 + 0.5) * size) + double(margin), glm::dvec2(0.0), size));
    if (b.x <= a.x || b.y <= a.y) return glm::ivec4(0);
    return {a.x, a.y, b.x - a.x, b.y - a.y};
}

// The ndc bounds (lower left, upper right) of spheres as one view sees them.
class SphereBounds {
public:
    explicit SphereBounds(const gpu::View& view)
        : view_(view),
          viewMatrix_(view.view),
          // Half the view's extent: in tan units (perspective) or metres (orthographic).
          half_(view.orthographic ? glm::dvec2(view.orthoHalfExtent) : glm::dvec2(view.tanHalfFovY * view.aspect, view.tanHalfFovY)) {}

    std::pair<glm::dvec2, glm::dvec2> operator()(const glm::dvec3& position, double r) const {
        const glm::dvec3 c(viewMatrix_ * glm::dvec4(position - view_.origin, 1.0));
        const double depth = -c.z;
        if (view_.orthographic) return {(glm::dvec2(c) - r) / half_, (glm::dvec2(c) + r) / half_};
        if (depth <= r) return {glm::dvec2(-1.0), glm::dvec2(1.0)};
        const glm::dvec2 x = tangentInterval(c.x, depth, r) / half_.x, y = tangentInterval(c.y, depth, r) / half_.y;
        return {{x[0], y[0]}, {x[1], y[1]}};
    }

private:
    const gpu::View& view_;
    glm::dmat4 viewMatrix_;
    glm::dvec2 half_;
};

// Whether a box's axis-aligned hull comes within `slack` of the particles' `bounds`: only those are
// tested particle by particle (a level of many meshes around one cloud).
bool hullNear(const OccluderBox& box, const Aabb& bounds, glm::dvec3 slack) {
    const glm::dvec3 hull = axisAlignedHalf(box);
    return !bounds.empty() && !glm::any(glm::greaterThan(box.centre - hull, bounds.max + slack)) &&
           !glm::any(glm::lessThan(box.centre + hull, bounds.min - slack));
}

// The slack hullNear needs for `reach` radii.
glm::dvec3 reachSlack(const ParticleSet& particles, double reach) {
    const double maxRadius = particles.empty() ? 0.0 : *std::max_element(particles.radius.begin(), particles.radius.end());
    return glm::dvec3(std::max(reach - 1.0, 0.0) * maxRadius);
}

}  // namespace

glm::ivec4 boxRect(const OccluderBox& box, const gpu::View& view, int margin) {
    const glm::dmat4 viewMatrix(view.view), projection(view.projection);
    glm::dvec2 lo(1e300), hi(-1e300);
    for (int corner = 0; corner < 8; ++corner) {
        glm::dvec3 p = box.centre;
        for (int a = 0; a < 3; ++a) p += box.axis[a] * (((corner >> a) & 1) != 0 ? box.half[a] : -box.half[a]);
        const glm::dvec4 v = viewMatrix * glm::dvec4(p - view.origin, 1.0);
        if (!view.orthographic && -v.z <= view.znear) return pixelRect(glm::dvec2(-1.0), glm::dvec2(1.0), view, margin);
        const glm::dvec4 clip = projection * v;
        lo = glm::min(lo, glm::dvec2(clip) / clip.w);
        hi = glm::max(hi, glm::dvec2(clip) / clip.w);
    }
    return pixelRect(lo, hi, view, margin);
}

glm::ivec4 unionRects(glm::ivec4 a, glm::ivec4 b) {
    if (a.z <= 0) return b;
    if (b.z <= 0) return a;
    const glm::ivec2 lo = glm::min(glm::ivec2(a), glm::ivec2(b));
    const glm::ivec2 hi = glm::max(glm::ivec2(a.x + a.z, a.y + a.w), glm::ivec2(b.x + b.z, b.y + b.w));
    return {lo.x, lo.y, hi.x - lo.x, hi.y - lo.y};
}

glm::ivec4 intersectRects(glm::ivec4 a, glm::ivec4 b) {
    const glm::ivec2 lo = glm::max(glm::ivec2(a), glm::ivec2(b));
    const glm::ivec2 hi = glm::min(glm::ivec2(a.x + a.z, a.y + a.w), glm::ivec2(b.x + b.z, b.y + b.w));
    if (hi.x <= lo.x || hi.y <= lo.y) return glm::ivec4(0);
    return {lo.x, lo.y, hi.x - lo.x, hi.y - lo.y};
}

glm::ivec4 billboardRect(const ParticleSet& particles, const std::vector<std::uint8_t>& which, const gpu::View& view, int margin) {
    const SphereBounds bounds(view);
    glm::dvec2 lo(1e300), hi(-1e300);
    for (std::size_t i = 0; i < particles.size() && i < which.size(); ++i) {
        if (which[i] == 0) continue;
        const auto [a, b] = bounds(particles.position[i], particles.radius[i]);
        lo = glm::min(lo, a);
        hi = glm::max(hi, b);
    }
    return pixelRect(lo, hi, view, margin);
}

std::vector<std::uint8_t> billboardsMeeting(const ParticleSet& particles, const gpu::View& view, glm::ivec4 rect) {
    const SphereBounds bounds(view);
    std::vector<std::uint8_t> meets(particles.size(), 0);
    for (std::size_t i = 0; i < particles.size(); ++i) {
        const auto [a, b] = bounds(particles.position[i], particles.radius[i]);
        meets[i] = intersectRects(pixelRect(a, b, view, 0), rect).z > 0 ? 1 : 0;
    }
    return meets;
}

glm::ivec4 nearMeshRect(const std::vector<OccluderBox>& meshes, const ParticleSet& particles, double reach, const gpu::View& view, int margin) {
    glm::ivec4 rect(0);
    const Aabb bounds = particleBounds(particles);
    const glm::dvec3 slack = reachSlack(particles, reach);
    std::vector<std::uint8_t> near(particles.size());
    for (const OccluderBox& box : meshes) {
        if (!hullNear(box, bounds, slack)) continue;
        bool any = false;
        for (std::size_t i = 0; i < particles.size(); ++i) {
            const double r = reach * particles.radius[i];
            near[i] = squaredDistance(box, particles.position[i]) < r * r ? 1 : 0;
            any = any || near[i] != 0;
        }
        // A ground under a cloud meets only the particles near it: its own rect, not the union's.
        if (any) rect = unionRects(rect, intersectRects(boxRect(box, view, margin), billboardRect(particles, near, view, margin)));
    }
    return rect;
}

glm::ivec4 meshEdgeRect(const std::vector<OccluderBox>& meshes, const ParticleSet& particles, const gpu::View& view, glm::ivec2 targetSize) {
    const glm::ivec2 full(view.width, view.height);
    if (targetSize == full || meshes.empty()) return glm::ivec4(0);
    const glm::vec2 perTexel = glm::vec2(full) / glm::vec2(glm::max(targetSize, glm::ivec2(1)));
    const int margin = static_cast<int>(std::ceil(std::max(perTexel.x, perTexel.y))) + 1;
    return nearMeshRect(meshes, particles, kEdgeReach, view, margin);
}

glm::ivec4 growRect(glm::ivec4 rect, int margin, const gpu::View& view) {
    if (rect.z <= 0 || margin == 0) return rect;
    return intersectRects(rect + glm::ivec4(-margin, -margin, 2 * margin, 2 * margin), {0, 0, view.width, view.height});
}

glm::ivec4 mediumRect(const ParticleSet& particles, const std::vector<Volume>& volumes, const gpu::View& view, int margin) {
    glm::ivec4 rect = billboardRect(particles, std::vector<std::uint8_t>(particles.size(), 1), view, margin);
    for (const Volume& v : volumes) rect = unionRects(rect, boxRect(occluderBox(v.world, -0.5 * v.size, 0.5 * v.size), view, margin));
    return rect;
}

std::vector<glm::dvec2> lampImages(const ParticleSet& particles, const std::vector<Light>& lights, const gpu::View& view) {
    const SphereBounds bounds(view);
    std::vector<glm::dvec2> images;
    for (std::size_t i = 0; i < lights.size(); ++i) {
        const Light& lamp = lights[i];
        const bool ahead = view.orthographic || glm::dot(lamp.position - view.origin, view.forward) > view.znear;
        if (lamp.kind != gpu::LightKind::Point || !ahead) continue;
        const int index[1] = {static_cast<int>(i)};
        const std::vector<std::uint8_t> near = particlesNearLamps(particles, lights, index, kLampReach);
        if (std::any_of(near.begin(), near.end(), [](std::uint8_t n) { return n != 0; }))
            images.push_back(bounds(lamp.position, 0.0).first);  // a point: both corners are it
    }
    return images;
}

LampPeaks lampPeaks(const std::vector<glm::dvec2>& images, const gpu::View& view, int margin) {
    LampPeaks peaks;
    for (const glm::dvec2& image : images) {
        const glm::ivec4 own = pixelRect(image, image, view, margin);
        peaks.rect = unionRects(peaks.rect, own);
        peaks.pixels += static_cast<long long>(own.z) * own.w;
    }
    return peaks;
}

bool lampPeaksCompact(const std::vector<glm::dvec2>& images, const gpu::View& view) {
    constexpr int kQuarterReach = 5;  // upsampleReach at ¼: a texel of 4 pixels and one more
    const LampPeaks peaks = lampPeaks(images, view, kQuarterReach);
    return static_cast<double>(peaks.rect.z) * peaks.rect.w <= kPeakRectSlack * static_cast<double>(peaks.pixels);
}

float automaticMediaScale(const SplatFootprint& footprint, double composed, bool lampBlurred) {
    if (footprint.coverage <= kHalfScaleCoverage * std::clamp(composed, 0.0, 1.0) || lampBlurred) return 1.0f;
    // Billboards too small to keep kAutoScaleRadiusTexels at ½ would lose their detail to any
    // reduction (a few texels each, on small images): they stay at full resolution.
    const double keeps = kAutoScaleRadiusTexels / footprint.radiusPixels;
    return keeps > 0.5 ? 1.0f : static_cast<float>(std::max(keeps, 0.25));
}

float automaticImpostorScale(double radiusTexels) {
    if (!(radiusTexels > 0.0)) return 0.5f;
    const double eighths = std::ceil(8.0 * kAutoImpostorRadiusTexels / radiusTexels - 1e-9);
    return static_cast<float>(std::clamp(eighths, 2.0, 4.0) / 8.0);
}

bool lampAmongParticles(const std::vector<Light>& lights, const Aabb& bounds, gpu::LightKind kind) {
    return std::any_of(lights.begin(), lights.end(), [&](const Light& l) { return l.kind == kind && bounds.contains(l.position); });
}

bool lampInsideMedium(const ParticleSet& particles, const std::vector<Light>& lights) {
    // Peak column through a particle's centre: σ ∫ e^{−k u²} du over the chord ≈ 0.8355·σR.
    constexpr double kColumnPerSigmaRadius = 0.8355;
    for (const auto& light : lights) {
        if (light.kind == gpu::LightKind::Directional) continue;
        for (std::size_t i = 0; i < particles.size(); ++i) {
            const double r = particles.radius[i];
            if (kColumnPerSigmaRadius * particles.sigma[i] * r > kLampMediumColumn && glm::length(light.position - particles.position[i]) < r)
                return true;
        }
    }
    return false;
}

bool meshReachesInto(const std::vector<OccluderBox>& meshes, const Aabb& bounds) {
    if (bounds.empty()) return false;
    return std::any_of(meshes.begin(), meshes.end(), [&](const OccluderBox& box) {
        const glm::dvec3 half = axisAlignedHalf(box);
        return glm::all(glm::lessThanEqual(box.centre - half, bounds.max)) && glm::all(glm::greaterThanEqual(box.centre + half, bounds.min));
    });
}

bool boxSpansMedium(const OccluderBox& box, const Aabb& bounds) {
    const glm::dvec3 half = axisAlignedHalf(box);
    // The axis the box is thinnest along is the one it does not span.
    const int thin = half.x <= half.y && half.x <= half.z ? 0 : (half.y <= half.z ? 1 : 2);
    for (int a = 0; a < 3; ++a)
        if (a != thin && (box.centre[a] - half[a] > bounds.min[a] || box.centre[a] + half[a] < bounds.max[a])) return false;
    return true;
}

std::vector<std::uint8_t> particlesNearMeshes(const std::vector<OccluderBox>& meshes, const ParticleSet& particles, double reach) {
    std::vector<std::uint8_t> near(particles.size(), 0);
    const Aabb bounds = particleBounds(particles);
    const glm::dvec3 slack = reachSlack(particles, reach);
    for (const OccluderBox& box : meshes) {
        if (!hullNear(box, bounds, slack)) continue;
        for (std::size_t i = 0; i < particles.size(); ++i) {
            const double r = reach * particles.radius[i];
            if (squaredDistance(box, particles.position[i]) < r * r) near[i] = 1;
        }
    }
    return near;
}

std::vector<std::uint8_t> particlesNearLamps(const ParticleSet& particles, const std::vector<Light>& lights, std::span<const int> lamps,
                                             double reach) {
    std::vector<std::uint8_t> near(particles.size(), 0);
    for (const int index : lamps) {
        if (index < 0) break;
        const Light& lamp = lights[static_cast<std::size_t>(index)];
        for (std::size_t i = 0; i < particles.size(); ++i) {
            const glm::dvec3 toParticle = particles.position[i] - lamp.position;
            const double d = glm::length(toParticle), r = particles.radius[i];
            bool isNear = d < reach * r;
            if (!isNear && lamp.kind == gpu::LightKind::Spot) {
                // The angle of its centre off the axis, ± the angle its sphere spans from the lamp.
                const double off = std::acos(std::clamp(glm::dot(toParticle / d, lamp.direction), -1.0, 1.0));
                const double spans = std::asin(std::min(r / d, 1.0));
                isNear = off + spans > lamp.innerConeAngle && off - spans < lamp.outerConeAngle;
            }
            if (isNear) near[i] = 1;
        }
    }
    return near;
}

std::vector<std::uint8_t> particlesClearOfMeshes(const std::vector<OccluderBox>& meshes, const ParticleSet& particles, const gpu::View& view) {
    // The margins keep the GPU's float tests (billboard.glsl: d ≤ 1.001 R, depth − R ≤ 2 near) on this side.
    constexpr double kMargin = 1.01;
    std::vector<std::uint8_t> clear(particles.size(), 0);
    std::vector<double> reach(particles.size(), 0.0);
    double slack = 0.0;  // the most a quad reaches beyond its sphere, for hullNear
    for (std::size_t i = 0; i < particles.size(); ++i) {
        const glm::dvec3 c = particles.position[i] - view.origin;
        const double r = particles.radius[i], d = glm::length(c), depth = glm::dot(c, view.forward);
        double half = r;  // an orthographic quad: screen-aligned, half size R
        if (!view.orthographic) {
            if (d <= kMargin * r || depth - r <= kMargin * 2.0 * view.znear) continue;
            half = r * d / std::sqrt(d * d - r * r);
        }
        clear[i] = 1;
        reach[i] = kMargin * half;
        slack = std::max(slack, reach[i] - r);
    }
    const Aabb bounds = particleBounds(particles);
    for (const OccluderBox& box : meshes) {
        if (!hullNear(box, bounds, glm::dvec3(slack))) continue;
        for (std::size_t i = 0; i < particles.size(); ++i)
            if (clear[i] != 0 && squaredDistance(box, particles.position[i]) < reach[i] * reach[i]) clear[i] = 0;
    }
    return clear;
}

bool eyeInsideMedium(const ParticleSet& particles, const gpu::View& view) {
    for (std::size_t i = 0; i < particles.size(); ++i) {
        const glm::dvec3 d = particles.position[i] - view.origin;
        // Orthographic rays start on the camera's plane: a particle crossing it holds their start.
        const double distance = view.orthographic ? std::abs(glm::dot(d, view.forward)) : glm::length(d);
        if (distance < particles.radius[i]) return true;
    }
    return false;
}

}  // namespace nimbus::media
