#pragma once
// Blocks mode (seed 000): per-frame block data on the GPU and the three passes that use it —
// impostors (for the camera and for each light view), the camera composite, and the light slices.
#include <cstdint>
#include <memory>
#include <vector>

#include "media_passes.h"
#include "nimbus/media/block_partition.h"
#include "nimbus/media/impostor_atlas.h"

namespace nimbus::media {

inline constexpr GLuint kImpostorItemsBinding = 6;
inline constexpr GLuint kBlockTilesBinding = 7;
inline constexpr GLuint kBlockNeighboursBinding = 10;  // shaders/media/block_order.glsl

struct alignas(16) GpuBlockTile {
    glm::vec4 rect;          // NDC rectangle in the view
    glm::vec4 atlas;         // tile in texels (width 0: not drawn)
    glm::vec4 centreRadius;  // origin-relative centre, mean particle radius
    glm::vec4 instance;      // x: ray-distance offset added to the tile's depths (instanced prototype; else 0);
                             // y: 1 when the tile has one texel per view pixel, on the pixel grid;
                             // z, w: the block's first impostor item and item count (w 0: an instance,
                             // whose particles are not in the item list)
    glm::vec4 lampSlices{0.0f};  // x: 1 when the lamps' slices hold the block's particles one by one
                                 // (blocksSeenWideFromLamps), not its light impostor; yzw free
};

// One view's impostor layout: where every block's tile is, and how big the atlas is.
struct BlockViewPlan {
    ImpostorView view;
    std::vector<GpuBlockTile> tiles;
    glm::ivec2 atlasSize{1, 1};
};

// `notDrawn` (per block, 1/0; empty: none): blocks whose tile this view leaves out (width 0), as a
// lamp's views leave out the blocks whose particles go into its slices one by one.
BlockViewPlan planBlockView(const BlockPartition& partition, const ImpostorView& view, const glm::dvec3& origin, float scale,
                            int maxAtlasSize, const std::vector<std::uint8_t>& notDrawn = {});

// Self-similar instancing: every block is drawn as a copy of block `prototype`, so the atlas holds
// one tile (the prototype's) that every block's rectangle maps onto, with its depths shifted by the
// block's distance from the prototype along the view.
BlockViewPlan planInstancedBlockView(const BlockPartition& partition, std::size_t prototype, const ImpostorView& view,
                                     const glm::dvec3& origin, float scale, int maxAtlasSize);

// The block whose bounding radius is the median: a representative prototype.
std::size_t choosePrototype(const BlockPartition& partition);

// The frame's blocks on the GPU: (particle, block) pairs in block order, every view's tiles (one
// range per view, all uploaded before the frame's first draw) and the camera's draw order.
// Nothing is rewritten between draws: llvmpipe does not order a buffer update after queued draws
// that read it (measured: with one tiles buffer rewritten per light view, the second light's
// slices were wrong until a glFinish was added between views).
class BlockGpuBuffers {
public:
    void uploadItems(const BlockPartition& partition);
    void uploadItems(const BlockPartition& partition, std::size_t onlyBlock);  // instancing: the prototype's particles
    void uploadTileSets(const std::vector<const BlockViewPlan*>& plans);
    void uploadDrawOrder(const std::vector<std::uint32_t>& blocks);
    void uploadOrderNeighbours(const std::vector<glm::uvec2>& lists);  // overlappingBlockLists
    // The particles the lamps' slices take one by one (blocksSeenWideFromLamps), for BlockSlicePass.
    void uploadLampSliceParticles(const std::vector<std::uint32_t>& particles);
    void bindLampSliceParticles() const;
    std::size_t lampSliceParticleCount() const { return lampSliceParticles_; }
    void bind(std::size_t tileSet) const;  // items, draw order, order neighbours and the tiles of one uploaded plan
    std::size_t itemCount() const { return items_; }

private:
    gpu::Buffer itemBuffer_, tileBuffer_, orderBuffer_, neighbourBuffer_, lampSliceBuffer_;
    std::size_t itemCapacity_ = 0, tileCapacity_ = 0, orderCapacity_ = 0, neighbourCapacity_ = 0, lampSliceCapacity_ = 0, items_ = 0,
                lampSliceParticles_ = 0;
    std::vector<std::pair<std::size_t, std::size_t>> tileRanges_;  // (byte offset, bytes) per tile set
};

// The atlas textures one impostor render writes (0: not written). depths (front, −back, τ) is
// always written; the camera also wants the weighted sums, the lights the depth moments.
struct ImpostorTargets {
    GLuint depths = 0;
    GLuint sums1 = 0;
    GLuint sums2 = 0;
    GLuint moments = 0;
};

// Renders a view's impostors into its atlas. Used by both the camera and the light passes.
class BlockImpostorRenderer {
public:
    BlockImpostorRenderer();
    void render(const BlockViewPlan& plan, std::size_t tileSet, const ImpostorTargets& targets, const BlockGpuBuffers& blocks,
                const ParticleGpuBuffer& particles) const;

private:
    gpu::Program program_;
    gpu::VertexArray vertexArray_ = gpu::createVertexArray();
};

// The camera's impostor atlas as frame-graph resources (the `block_impostors` pass).
struct BlockImpostorAtlas {
    render::ResourceHandle depths, sums1, sums2, moments;
};
// Adds the `block_impostors` pass: the camera's plan (tile set 0 of `blocks`) rendered into a new atlas.
BlockImpostorAtlas addBlockImpostorPass(render::FrameGraph& graph, const BlockViewPlan& plan, const BlockGpuBuffers& blocks,
                                        const ParticleGpuBuffer& particles, const BlockImpostorRenderer& impostors);

// A mesh instance's bounds in world space: its local box carried by the instance's rotation and
// scale (a wing tilted through a cloud has an axis-aligned box as big as the cloud), or, where the
// transform shears, the axis-aligned box around that.
struct MeshBox {
    glm::dvec3 centre{0.0};
    glm::dvec3 axis[3] = {glm::dvec3(1.0, 0.0, 0.0), glm::dvec3(0.0, 1.0, 0.0), glm::dvec3(0.0, 0.0, 1.0)};  // orthonormal
    glm::dvec3 half{0.0};  // half extents along the axes
};

// The box of every mesh instance the frame draws (what can write scene depth).
std::vector<MeshBox> meshInstanceBoxes(const render::FrameInput& input);

// Per block (1/0): whether a mesh may pass among its particles, i.e. its bounding sphere, widened
// by its mean particle radius (the kernel tails past [front, back] that block_composite.frag's cut
// reaches), meets one of `meshes`. Only those blocks are composited with the exact cut through their
// own particles (BLOCK_EXACT_CUT): llvmpipe pays for that code in every pixel of the draw, taken or
// not (cumulus.gltf at 1280×720, where no mesh comes near: 925 ms → 762 ms without it).
std::vector<std::uint8_t> blocksNearMeshes(const BlockPartition& partition, const std::vector<MeshBox>& meshes);

// Blocks of at most this many particles may be shaded from their own particles (below).
inline constexpr std::uint32_t kMaxOwnShadedBlockParticles = 64;  // block_own_optical_depth.glsl walks them per texel ray

// Whether light view v's slices resolve a particle of radius R and peak extinction σ at `centre`
// (origin-relative): slice planes and texels no farther apart than it is wide and neither holding
// more than an optical depth of 2 of it (shaders/media/own_optical_depth.glsl slicesResolve).
bool sliceViewResolves(const render::GpuLightView& v, const glm::dvec3& centre, double radius, double sigma);

// Per block (1/0): whether it is shaded from its own particles (BLOCK_OWN_PARTICLES,
// shaders/media/block_own_optical_depth.glsl): it has at most kMaxOwnShadedBlockParticles, and a
// light view's slices do not resolve one of them at the block's centre (sliceViewResolves). Such
// a block is lumps, not the smooth medium its depth profile stands for. `views`: the frame's
// transmittance views (origin-relative, as packed for the shaders); `origin`: the frame origin.
// llvmpipe runs that code in every pixel of a draw, taken or not (cumulus.gltf 640×360: the
// composite pass 940 → 1440 ms), so only these blocks are drawn with it.
std::vector<std::uint8_t> blocksOfUnresolvedParticles(const BlockPartition& partition, const ParticleSet& particles,
                                                       const std::vector<render::GpuLightView>& views, const glm::dvec3& origin);

// Per block (1/0): whether it is composited with BLOCK_EXACT_SHADING (block_shading seam or exact),
// where a mesh is seen inside the medium: it comes near one of `meshes` (blocksNearMeshes), or it
// may lie in front of one that passes among the blocks (its rectangle in `cameraPlan` meets the mesh
// box's on the screen, and it reaches nearer than the box's far side). Such a block is shaded at up
// to 16 points placed by its own particles, with its overlapping neighbours' attenuation made exact
// (shaders/media/block_order.glsl, overlappingBlockLists): over its whole rectangle (exact), or
// only near the texels where a mesh lies among the particles (seam, BlockSeamMaskPass). The default
// smooth shading is cheaper, and its errors and the compositing order's partly cancel; where a seam
// shows they did not on fresh make_block_scenes.py seeds (9600/08, 9800/01, 9900/09: small dense
// particles shaded at uniform points; 9700/08: big overlapping ones, dark from the order). The
// exact code costs about 7× the smooth per texel on llvmpipe: 16 lit points instead of two, each
// with its mesh shadow search, and every neighbour's profile read at every texel (docs/PERFORMANCE.md).
// Not with instancing: an instance's particles are not listed.
std::vector<std::uint8_t> blocksShadedExactly(const BlockPartition& partition, const std::vector<MeshBox>& meshes,
                                              const BlockViewPlan& cameraPlan, const render::View& view);

// The composite build a block is drawn with: which of the optional parts it needs.
enum BlockCompositeBuild : std::uint8_t {
    kBlockPlain = 0,
    kBlockExactCut = 1,       // BLOCK_EXACT_CUT: a mesh comes near (blocksNearMeshes)
    kBlockOwnParticles = 2,   // BLOCK_OWN_PARTICLES: lumps the slices do not resolve (blocksOfUnresolvedParticles)
    kBlockExactShading = 4,   // BLOCK_EXACT_SHADING: where a mesh is seen in the medium (blocksShadedExactly)
};

// Consecutive ranks of the camera's back-to-front order, drawn as one instanced draw.
struct BlockRankRun {
    GLint first = 0;
    GLsizei count = 0;
};

// Media texels per seam mask texel, per axis, for a media target of `size`: about a 48th of its
// shorter side, at least 4. The exact shading reaches half a cell past the texels where a mesh lies
// in the medium and fades out over the next cell (shaders/media/block_seam.glsl seamWeight), so that
// fade is as wide a share of the image at any resolution (a fixed 4 texels left a visible edge
// where the smooth and exact shadings differ by 3%, as on cloud.gltf).
int seamMaskCell(glm::ivec2 size);

// The seam mask (shaders/media/block_seam.glsl): one R8 texel per cell of seamMaskCell² texels of
// the media target, 1 where, at one of them, the opaque surface lies among the particles of a block
// drawn by `runs` (within its impostor's [front − reach, back + reach]), i.e. where a mesh is seen
// inside the medium. Draws the blocks' rectangles widened by a cell, one fragment per cell.
//
// Does not: widen the mask or smooth its edge (block_seam.glsl seamWeight does, where it is read).
class BlockSeamMaskPass {
public:
    BlockSeamMaskPass();
    struct Output {
        render::ResourceHandle mask;     // R8, one texel per cell
        render::ResourceHandle stencil;  // the media target's size: stencil 1 where seamWeight > 0
    };
    Output add(render::FrameGraph& graph, render::FrameContext& context, std::vector<BlockRankRun> runs, const BlockGpuBuffers& blocks,
               render::ResourceHandle impostorDepths, const MediaTarget& target, int cell);

private:
    gpu::Program program_;
    gpu::Program stencilProgram_;
    gpu::VertexArray vertexArray_ = gpu::createVertexArray();
};

// Camera: impostors into an atlas, then blocks composited back to front into the media target.
// The composite program (block_composite.*) for a BlockCompositeBuild.
gpu::ProgramDesc blockCompositeDesc(std::uint8_t build);

class BlockCompositePass {
public:
    BlockCompositePass();
    // The camera's plan is tile set 0 of `blocks`; `builds`: each block's BlockCompositeBuild bits.
    // `seamOnly` (block_shading=seam): the BLOCK_EXACT_SHADING blocks are shaded exactly only near the
    // texels where a mesh lies among the particles of the blocks a mesh comes near (BlockSeamMaskPass),
    // and smoothly elsewhere, blended over a mask cell (block_seam.glsl seamWeight).
    render::ResourceHandle add(render::FrameGraph& graph, render::FrameContext& context, const BlockImpostorAtlas& atlas,
                               const std::vector<std::uint32_t>& backToFront, const std::vector<std::uint8_t>& builds,
                               bool seamOnly, const BlockGpuBuffers& blocks, const ParticleGpuBuffer& particles,
                               const MediaTarget& target);

private:
    LocalLightPrograms& programs(std::uint8_t build);  // compiled when first asked for

    std::unique_ptr<LocalLightPrograms> programs_[8];  // by BlockCompositeBuild bits
    std::unique_ptr<BlockSeamMaskPass> seamMask_;      // made when a frame first needs it
    gpu::VertexArray vertexArray_ = gpu::createVertexArray();
};

inline constexpr GLuint kLampSliceParticlesBinding = 9;  // shaders/media/light_slices.vert SLICE_PARTICLE_LIST

// Light slices from blocks: per light view, light impostors, then each block spread over the slices;
// a lamp's views also take the particles of the blocks it sees wide one by one, as particles mode does.
class BlockSlicePass {
public:
    BlockSlicePass();
    // Light view i's plan is tile set i + 1 of `blocks`.
    render::ResourceHandle add(render::FrameGraph& graph, const std::vector<SliceView>& views,
                               const std::vector<BlockViewPlan>& plans, int resolution, const BlockGpuBuffers& blocks,
                               const ParticleGpuBuffer& particles, const BlockImpostorRenderer& impostors);

private:
    gpu::Program program_;
    gpu::Program particleProgram_;  // light_slices.* over the lamp slice particles
    gpu::VertexArray vertexArray_ = gpu::createVertexArray();
};

}  // namespace nimbus::media
