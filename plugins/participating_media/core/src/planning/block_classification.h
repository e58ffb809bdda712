#pragma once
// Blocks mode planning: which optional parts of the composite each block is drawn with.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "nimbus/gpu/frame_layout.h"
#include "nimbus/gpu/view.h"
#include "nimbus/media/block_partition.h"
#include "nimbus/media/host.h"
#include "nimbus/media/particle_set.h"
#include "planning/block_view_plan.h"

namespace nimbus::media {

// Per block (1/0): whether a mesh may pass among its particles, i.e. its bounding sphere, widened
// by its mean particle radius (the kernel tails past [front, back] that block_composite.frag's cut
// reaches), meets one of `meshes`. Only those blocks are composited with the exact cut through their
// own particles (BLOCK_EXACT_CUT): llvmpipe pays for that code in every pixel of the draw, taken or
// not (docs/design-notes.md).
std::vector<std::uint8_t> blocksNearMeshes(const BlockPartition& partition, const std::vector<OccluderBox>& meshes);

// Blocks of at most this many particles may be shaded from their own particles (below).
inline constexpr std::uint32_t kMaxOwnShadedBlockParticles = 64;  // block_own_optical_depth.glsl walks them per texel ray

// Whether light view v's slices resolve a particle of radius R and peak extinction σ at `centre`
// (origin-relative): slice planes and texels no farther apart than it is wide and neither holding
// more than an optical depth of 2 of it (shaders/media/common/own_optical_depth.glsl slicesResolve).
bool sliceViewResolves(const gpu::GpuLightView& v, const glm::dvec3& centre, double radius, double sigma);

// Per block (1/0): whether it is shaded from its own particles (BLOCK_OWN_PARTICLES,
// shaders/media/blocks/block_own_optical_depth.glsl): it has at most kMaxOwnShadedBlockParticles, and a
// light view's slices do not resolve one of them at the block's centre (sliceViewResolves). Such
// a block is lumps, not the smooth medium its depth profile stands for. `views`: the frame's
// transmittance views (origin-relative, as packed for the shaders); `origin`: the frame origin.
// llvmpipe runs that code in every pixel of a draw, taken or not (docs/design-notes.md), so only
// these blocks are drawn with it.
std::vector<std::uint8_t> blocksOfUnresolvedParticles(const BlockPartition& partition, const ParticleSet& particles,
                                                       const std::vector<gpu::GpuLightView>& views, const glm::dvec3& origin);

// Per block (1/0): whether it is composited with BLOCK_EXACT_SHADING (block_shading seam or exact),
// where a mesh is seen inside the medium: it comes near one of `meshes` (blocksNearMeshes), or it
// may lie in front of one that passes among the blocks (its rectangle in `cameraPlan` meets the mesh
// box's on the screen, and it reaches nearer than the box's far side). Such a block is shaded at up
// to 16 points placed by its own particles, with its overlapping neighbours' attenuation made exact
// (shaders/media/blocks/block_order.glsl, overlappingBlockLists): over its whole rectangle (exact), or
// only near the texels where a mesh lies among the particles (seam, BlockSeamMaskPass). The default
// smooth shading is cheaper, and its errors and the compositing order's partly cancel, but not for
// small dense particles shaded at uniform points, or big overlapping ones (dark from the order). The
// exact code costs several times the smooth per texel on llvmpipe: 16 lit points instead of two, each
// with its mesh shadow search, and every neighbour's profile read at every texel (docs/design-notes.md).
// Not with instancing: an instance's particles are not listed.
std::vector<std::uint8_t> blocksShadedExactly(const BlockPartition& partition, const std::vector<OccluderBox>& meshes,
                                              const BlockViewPlan& cameraPlan, const gpu::View& view);

// The composite build a block is drawn with: which of the optional parts it needs.
enum BlockCompositeBuild : std::uint8_t {
    kBlockPlain = 0,
    kBlockExactCut = 1,       // BLOCK_EXACT_CUT: a mesh comes near (blocksNearMeshes)
    kBlockOwnParticles = 2,   // BLOCK_OWN_PARTICLES: lumps the slices do not resolve (blocksOfUnresolvedParticles)
    kBlockExactShading = 4,   // BLOCK_EXACT_SHADING: where a mesh is seen in the medium (blocksShadedExactly)
    kBlockLitImpostor = 8,    // BLOCK_LIT_IMPOSTOR: its light read from the impostor texels' (block_lighting=texel)
};

}  // namespace nimbus::media
