#include "nimbus/media/impostor_atlas.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace nimbus::media {
namespace {

constexpr int kMinTile = 4;
constexpr int kMaxTile = 256;

bool shelfPack(const std::vector<glm::ivec2>& sizes, const std::vector<std::size_t>& byHeight, int maxSize,
               std::vector<AtlasTile>& tiles, int& usedWidth, int& usedHeight) {
    int x = 0, y = 0, shelf = 0;
    usedWidth = usedHeight = 0;
    for (std::size_t i : byHeight) {
        const glm::ivec2 s = sizes[i];
        if (s.x <= 0 || s.y <= 0) {
            tiles[i] = {};
            continue;
        }
        if (x + s.x > maxSize) {  // next shelf
            y += shelf;
            x = 0;
            shelf = 0;
        }
        if (y + s.y > maxSize) return false;
        tiles[i] = {x, y, s.x, s.y};
        x += s.x + (s.x & 1);  // the next tile starts at an even texel (kTileAlignment)
        shelf = std::max(shelf, s.y + (s.y & 1));
        usedWidth = std::max(usedWidth, x);
        usedHeight = std::max(usedHeight, y + shelf);
    }
    return true;
}

}  // namespace

AtlasLayout packAtlas(const std::vector<glm::ivec2>& requested, int maxSize) {
    AtlasLayout layout;
    layout.tiles.resize(requested.size());
    std::vector<std::size_t> byHeight(requested.size());
    std::iota(byHeight.begin(), byHeight.end(), std::size_t{0});
    std::stable_sort(byHeight.begin(), byHeight.end(), [&](std::size_t a, std::size_t b) { return requested[a].y > requested[b].y; });
    std::vector<glm::ivec2> sizes = requested;
    for (int attempt = 0; attempt < 64; ++attempt) {
        if (shelfPack(sizes, byHeight, maxSize, layout.tiles, layout.width, layout.height)) break;
        layout.shrink *= 0.85f;
        for (std::size_t i = 0; i < sizes.size(); ++i)
            if (requested[i].x > 0)
                sizes[i] = glm::max(glm::ivec2(glm::floor(glm::vec2(requested[i]) * layout.shrink)), glm::ivec2(1));
    }
    layout.width = std::max(layout.width, 1);
    layout.height = std::max(layout.height, 1);
    return layout;
}

glm::vec2 rectanglePixels(const glm::vec4& rect, const glm::ivec2& viewport) {
    return glm::vec2(rect.z - rect.x, rect.w - rect.y) * 0.5f * glm::vec2(viewport);
}

std::vector<BlockFootprint> blockFootprints(const BlockPartition& partition, const ImpostorView& view, const glm::dvec3& origin) {
    std::vector<BlockFootprint> footprints;
    footprints.reserve(partition.blocks.size());
    const glm::dmat4 viewMatrix(view.view);
    const glm::dmat4 projection = glm::dmat4(view.viewProjection) * glm::inverse(viewMatrix);
    const glm::dvec2 viewport(view.viewport);
    // Pixels per unit of view-space length at clip w = 1 (the smaller axis: a round particle).
    const double pixelsPerUnit = 0.5 * std::min(std::abs(projection[0][0]) * viewport.x, std::abs(projection[1][1]) * viewport.y);
    for (const Block& b : partition.blocks) {
        const glm::dvec3 c = glm::dvec3(viewMatrix * glm::dvec4(b.centre - origin, 1.0));
        BlockFootprint footprint;
        const double w = view.perspective ? std::max(-c.z, static_cast<double>(view.nearDepth)) : 1.0;
        footprint.particlePixels = static_cast<float>(b.meanParticleRadius * pixelsPerUnit / std::max(w, 1e-30));
        glm::dvec2 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
        if (view.perspective && -c.z - b.radius <= static_cast<double>(view.nearDepth)) {
            if (-c.z + b.radius <= static_cast<double>(view.nearDepth)) {
                footprints.push_back({});  // wholly behind: nothing to draw
                continue;
            }
            lo = glm::dvec2(-1.0), hi = glm::dvec2(1.0);  // crosses the near plane: be conservative
        } else {
            for (int k = 0; k < 8; ++k) {
                const glm::dvec3 corner = c + b.radius * glm::dvec3(k & 1 ? 1 : -1, k & 2 ? 1 : -1, k & 4 ? 1 : -1);
                const glm::dvec4 clip = projection * glm::dvec4(corner, 1.0);
                const glm::dvec2 ndc = glm::dvec2(clip) / clip.w;
                lo = glm::min(lo, ndc);
                hi = glm::max(hi, ndc);
            }
            const glm::dvec2 pixels = (hi - lo) * 0.5 * viewport;
            const double discs = b.count * 3.14159265358979 * footprint.particlePixels * footprint.particlePixels;
            if (pixels.x > 0.0 && pixels.y > 0.0) footprint.overdraw = static_cast<float>(discs / (pixels.x * pixels.y));
        }
        // Out to whole pixels, so a tile of one texel per pixel has its texel centres on pixel centres.
        lo = glm::floor((glm::clamp(lo, -1.0, 1.0) * 0.5 + 0.5) * viewport) / viewport * 2.0 - 1.0;
        hi = glm::ceil((glm::clamp(hi, -1.0, 1.0) * 0.5 + 0.5) * viewport) / viewport * 2.0 - 1.0;
        if (hi.x > lo.x && hi.y > lo.y) footprint.rect = glm::vec4(lo.x, lo.y, hi.x, hi.y);
        footprints.push_back(footprint);
    }
    return footprints;
}

std::vector<glm::ivec2> tileSizes(const std::vector<BlockFootprint>& footprints, const glm::ivec2& viewport, float scale) {
    std::vector<glm::ivec2> sizes;
    sizes.reserve(footprints.size());
    for (const BlockFootprint& f : footprints) {
        const glm::vec4& r = f.rect;
        if (r.z <= r.x || r.w <= r.y) {
            sizes.emplace_back(0);
            continue;
        }
        // A tile on the pixel grid keeps one texel per pixel however small; others get kMinTile.
        const bool perPixel = scale <= 1.0f && (f.particlePixels * scale < kResolvedParticleTexels || f.overdraw <= kPerPixelOverdraw);
        const float density = perPixel ? 1.0f : scale;
        const glm::ivec2 texels(glm::ceil(rectanglePixels(r, viewport) * density - 1e-3f));  // a snapped rectangle's float pixels may be n + ε
        sizes.emplace_back(glm::clamp(texels, glm::ivec2(perPixel ? 1 : kMinTile), glm::ivec2(kMaxTile)));
    }
    return sizes;
}

}  // namespace nimbus::media
