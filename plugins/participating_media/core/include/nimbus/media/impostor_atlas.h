#pragma once
// Where each block's depth impostor lives in an atlas texture, and which part of a view it covers.
// The tile resolution follows the block's size in the view (Umenhoffer and Szirmay-Kalos: an impostor needs no more
// texels than the pixels it covers), times a quality scale.
#include <limits>
#include <vector>

#include <glm/glm.hpp>

#include "nimbus/media/block_partition.h"
#include "nimbus/gpu/light_views.h"

namespace nimbus::media {

struct AtlasTile {
    int x = 0, y = 0, width = 0, height = 0;  // texels; width 0: the block is not visible
};

// Shelf-packs tiles of the requested sizes into an atlas no larger than maxSize per side, shrinking
// every tile by the same factor until they fit. Deterministic (tallest first, ties by index).
// Tiles start at multiples of kTileAlignment texels, so an atlas of half the resolution holds each
// tile's texels two by two without overlap (the blocks' light, block_impostor_lighting_pass.h).
inline constexpr int kTileAlignment = 2;
struct AtlasLayout {
    int width = 0, height = 0;
    std::vector<AtlasTile> tiles;  // in the order of the requested sizes
    float shrink = 1.0f;           // how much the sizes were scaled down to fit
};
AtlasLayout packAtlas(const std::vector<glm::ivec2>& sizes, int maxSize);

// A view to render impostors for: the camera or a light view (matrices origin-relative).
struct ImpostorView {
    glm::mat4 view{1.0f};
    glm::mat4 viewProjection{1.0f};
    bool perspective = true;
    glm::vec3 eye{0.0f};          // origin-relative position of the eye (perspective)
    float nearDepth = 0.0f;       // view depth of the near plane
    glm::ivec2 viewport{1, 1};    // pixels (the camera) or texels (a light view's slices)
};

// A block as one view sees it.
struct BlockFootprint {
    glm::vec4 rect{0.0f};          // NDC xy min, zw max: clipped to [-1, 1]², widened to whole viewport pixels
    float particlePixels = 0.0f;   // the block's mean particle radius in viewport pixels, at the block's centre
    // The block's particle discs' summed area over its rectangle's (before clipping): how many
    // particles an impostor texel sums on average. Infinite where unknown (a block through the near plane).
    float overdraw = std::numeric_limits<float>::infinity();
};

// How many viewport pixels a footprint's rectangle spans per axis (whole numbers, up to float error).
glm::vec2 rectanglePixels(const glm::vec4& rect, const glm::ivec2& viewport);

// Each block's footprint; a zero-area rectangle when the block is off-view. A block that reaches
// behind the near plane covers the whole view.
std::vector<BlockFootprint> blockFootprints(const BlockPartition& partition, const ImpostorView& view, const glm::dvec3& origin);

// Tile sizes for those footprints: rectangle pixels × texel density, clamped to [4, 256] per side.
// The density is `scale`, raised to one texel per pixel for a block whose particles would be less
// than kResolvedParticleTexels texels in radius, or that sums no more than kPerPixelOverdraw
// particles per texel: such a tile samples every pixel centre's own ray (the rectangle is on the
// pixel grid), as the composite, `particles` mode and the reference do.
// Why 4: a particle is a Gaussian of deviation σ = R/3, and bilinear reconstruction from texels h
// apart errs by up to h²/(8σ²) of its peak: 7% at 4 texels per radius, 28% at 2, and a particle
// under one texel is lost or spread (docs/design-notes.md).
// Why the overdraw: where particles overlap, their sum curves far less than one kernel does; a lone
// particle keeps the full h²/(8σ²), which a sharp phase peak magnifies (docs/design-notes.md). At one
// layer or less, one texel per pixel costs the impostor pass at most as many fragments as the
// composite already draws for the block.
inline constexpr float kResolvedParticleTexels = 4.0f;
inline constexpr float kPerPixelOverdraw = 1.0f;
std::vector<glm::ivec2> tileSizes(const std::vector<BlockFootprint>& footprints, const glm::ivec2& viewport, float scale);

}  // namespace nimbus::media
