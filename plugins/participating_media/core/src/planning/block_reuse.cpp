#include "planning/block_reuse.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace nimbus::media {
namespace {

// The angle between two directions, robust near 0 (atan2 of |a × b| and a · b).
double angleBetween(const glm::dvec3& a, const glm::dvec3& b) { return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)); }

// How far the block's centre lies along the view, and its screen scale: NDC units per metre at
// its depth (a row of the view-projection has the projection's scale as its length; the view is a
// rotation).
double viewDepth(const WorldView& v, const glm::dvec3& centre) { return glm::dot(centre - v.origin, v.forward); }
double ndcPerMetre(const WorldView& v, const glm::dvec3& centre) {
    const double row = glm::length(glm::dvec3(v.viewProjection[0][1], v.viewProjection[1][1], v.viewProjection[2][1]));
    return v.perspective ? row / std::max(viewDepth(v, centre), 1e-30) : row;
}

// The ray distance tileMomentOrigin (block_data.glsl) takes a tile's depths about.
double momentOrigin(const WorldView& v, const glm::dvec3& centre) {
    return v.perspective ? glm::length(centre - v.origin) : viewDepth(v, centre);
}

glm::dvec2 toNdc(const glm::dmat4& viewProjection, const glm::dvec3& relative) {
    const glm::dvec4 clip = viewProjection * glm::dvec4(relative, 1.0);
    return glm::dvec2(clip) / clip.w;
}

// Whether the block's bounding cube (blockFootprints' rectangle before clipping) lies inside the view.
bool wholeInView(const WorldView& v, const Block& block) {
    const glm::dvec3 c = block.centre - v.origin;
    for (int k = 0; k < 8; ++k) {
        const glm::dvec3 corner = c + block.radius * glm::dvec3(k & 1 ? 1 : -1, k & 2 ? 1 : -1, k & 4 ? 1 : -1);
        const glm::dvec2 ndc = toNdc(v.viewProjection, corner);
        if (std::abs(ndc.x) > 1.0 || std::abs(ndc.y) > 1.0) return false;
    }
    return true;
}

bool crossesNearPlane(const WorldView& v, const Block& block) {
    return v.perspective && viewDepth(v, block.centre) - block.radius <= v.znear;
}

// Now's NDC → then's clip (x, y, w) at the block centre's depth in now's view: three columns.
struct Homography {
    glm::dvec4 x, y, one;
    glm::dvec3 apply(const glm::dvec2& ndc) const {
        const glm::dvec4 clip = ndc.x * x + ndc.y * y + one;
        return {clip.x, clip.y, clip.w};
    }
};
Homography homography(const WorldView& then, const WorldView& now, const glm::dvec3& centre) {
    const glm::dvec4 c = now.viewProjection * glm::dvec4(centre - now.origin, 1.0);
    const glm::dmat4 map = then.viewProjection * glm::translate(glm::dmat4(1.0), now.origin - then.origin) * glm::inverse(now.viewProjection);
    return {map[0], map[1], map * glm::dvec4(0.0, 0.0, c.z / c.w, 1.0)};
}

// Whether every corner of now's rectangle falls inside then's, up to half a texel.
bool covered(const Homography& h, const GpuBlockTile& then, const glm::vec4& nowRect) {
    const glm::dvec2 lo(then.rect.x, then.rect.y), hi(then.rect.z, then.rect.w);
    const glm::dvec2 slack = 0.5 * (hi - lo) / glm::dvec2(then.atlas.z, then.atlas.w);
    for (int k = 0; k < 4; ++k) {
        const glm::dvec3 clip = h.apply({k & 1 ? nowRect.z : nowRect.x, k & 2 ? nowRect.w : nowRect.y});
        if (!(clip.z > 0.0)) return false;
        const glm::dvec2 ndc = glm::dvec2(clip) / clip.z;
        if (glm::any(glm::lessThan(ndc, lo - slack)) || glm::any(glm::greaterThan(ndc, hi + slack))) return false;
    }
    return true;
}

ReuseVerdict judgeBlock(const Block& block, const GpuBlockTile& then, const WorldView& thenView, const GpuBlockTile& now,
                        const WorldView& nowView, const ImpostorReuseLimits& limits) {
    if (!(then.atlas.z > 0.0f)) return ReuseVerdict::Uncovered;
    if (crossesNearPlane(thenView, block) || crossesNearPlane(nowView, block)) return ReuseVerdict::NearPlane;
    const double turned = thenView.perspective ? angleBetween(block.centre - thenView.origin, block.centre - nowView.origin)
                                               : angleBetween(thenView.forward, nowView.forward);
    if (turned > glm::radians(limits.degrees)) return ReuseVerdict::Turned;
    const double scale = ndcPerMetre(nowView, block.centre) / ndcPerMetre(thenView, block.centre);
    if (scale > limits.scale || scale < 1.0 / limits.scale) return ReuseVerdict::Scaled;
    if (!wholeInView(thenView, block) && !covered(homography(thenView, nowView, block.centre), then, now.rect))
        return ReuseVerdict::Uncovered;
    return ReuseVerdict::Reused;
}

// `now` reads `then`'s tile: then's NDC → atlas texels after the homography, rows scaled so w is
// about 1 at the tile.
void readThrough(GpuBlockTile& now, const GpuBlockTile& then, const Homography& h, double depthShift) {
    const glm::dvec2 size(then.rect.z - then.rect.x, then.rect.w - then.rect.y);
    const glm::dvec2 s = glm::dvec2(then.atlas.z, then.atlas.w) / size;
    const glm::dvec2 o = glm::dvec2(then.atlas.x, then.atlas.y) - glm::dvec2(then.rect.x, then.rect.y) * s;
    const glm::dvec3 w(h.x.w, h.y.w, h.one.w);
    const glm::dvec3 rowX = s.x * glm::dvec3(h.x.x, h.y.x, h.one.x) + o.x * w;
    const glm::dvec3 rowY = s.y * glm::dvec3(h.x.y, h.y.y, h.one.y) + o.y * w;
    const double norm = std::abs(h.one.w) > 0.0 ? 1.0 / std::abs(h.one.w) : 1.0;
    now.reproject[0] = glm::vec4(glm::vec3(rowX * norm), 1.0f);
    now.reproject[1] = glm::vec4(glm::vec3(rowY * norm), 0.0f);
    now.reproject[2] = glm::vec4(glm::vec3(w * norm), 0.0f);
    now.atlas = then.atlas;
    now.instance.x = static_cast<float>(depthShift);
    now.instance.y = 0.0f;  // read bilinearly: its texels are no longer on the pixel grid
}

}  // namespace

const char* reuseVerdictName(ReuseVerdict verdict) {
    switch (verdict) {
        case ReuseVerdict::Reused: return "reused";
        case ReuseVerdict::Changed: return "changed";
        case ReuseVerdict::Turned: return "turned";
        case ReuseVerdict::Scaled: return "scaled";
        case ReuseVerdict::Uncovered: return "uncovered";
        case ReuseVerdict::NearPlane: return "near plane";
    }
    return "?";
}

ReuseVerdict reuseCameraTiles(const BlockPartition& partition, const BlockViewPlan& then, const WorldView& thenView,
                              const WorldView& nowView, const ImpostorReuseLimits& limits, BlockViewPlan& now) {
    if (then.tiles.size() != partition.blocks.size() || now.tiles.size() != partition.blocks.size() ||
        thenView.perspective != nowView.perspective)
        return ReuseVerdict::Changed;  // planned for another partition or projection
    if (!(limits.degrees > 0.0)) return ReuseVerdict::Turned;  // any turn is too far
    // The same view plans the same tiles (`now` is `then`): read them as they are, to the bit.
    if (thenView.origin == nowView.origin && thenView.viewProjection == nowView.viewProjection) return ReuseVerdict::Reused;
    for (std::size_t b = 0; b < partition.blocks.size(); ++b) {
        if (!(now.tiles[b].atlas.z > 0.0f)) continue;  // not seen now
        const ReuseVerdict verdict = judgeBlock(partition.blocks[b], then.tiles[b], thenView, now.tiles[b], nowView, limits);
        if (verdict != ReuseVerdict::Reused) return verdict;
    }
    for (std::size_t b = 0; b < partition.blocks.size(); ++b) {
        if (!(now.tiles[b].atlas.z > 0.0f)) continue;
        const glm::dvec3& centre = partition.blocks[b].centre;
        readThrough(now.tiles[b], then.tiles[b], homography(thenView, nowView, centre),
                    momentOrigin(nowView, centre) - momentOrigin(thenView, centre));
    }
    now.atlasSize = then.atlasSize;
    return ReuseVerdict::Reused;
}

}  // namespace nimbus::media
