#pragma once
// `blocks` (Umenhoffer and Szirmay-Kalos's particle hierarchies with depth impostors): the particles grouped
// into blocks, each block's depth impostor rendered for the camera and every light view, composited back to
// front, with the blocks a mesh reaches cut at it.
#include <cstdint>

#include "nimbus/base/quality_tier.h"
#include "nimbus/media/technique.h"

namespace nimbus::media {

// How the blocks are shaded where a mesh is seen inside the medium (planning/block_classification.h
// blocksShadedExactly): exactly is at up to 16 points placed by their own particles, with the
// compositing order of overlapping blocks corrected; smoothly is at two points of each block's
// depth profile, as everywhere else. In the order of the block_shading words.
enum class BlockShading : std::uint8_t {
    Seam,    // exactly near the texels where a mesh lies among the particles, smoothly elsewhere
    Smooth,  // smoothly everywhere: fastest, but can show a seam (docs/design-notes.md)
    Exact,   // exactly over those blocks' whole rectangles
};

// Where the light of a block no mesh comes near is evaluated. In the order of the block_lighting words.
enum class BlockLighting : std::uint8_t {
    Pixel,  // at every media texel the block covers
    Texel,  // once per texel of its impostor, read back bilinearly (blocks/block_impostor_lighting_pass.h)
};

struct BlocksSettings {
    int blocks = 0;              // block count; 0: automatic (block_partition.h)
    float impostorScale = 0.0f;  // impostor texels per covered pixel; 0: 0.5
    bool impostorScaleAuto = false;  // chosen each frame from the billboards' size (automaticImpostorScale)
    bool instancing = false;     // one block prototype instanced at every block (the paper's b + N/b)
    BlockShading blockShading = BlockShading::Seam;
    BlockLighting lighting = BlockLighting::Pixel;
    // impostor_reuse: the most degrees any block's direction from the eye may turn while the
    // camera's impostors are read again (planning/block_reuse.h); 0: rendered every frame.
    float reuseDegrees = 0.0f;

    static BlocksSettings forTier(QualityTier tier);
};

TechniqueEntry blocksTechnique();

}  // namespace nimbus::media
