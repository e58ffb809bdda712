#pragma once
// The participating media in the real-time frame (DESIGN.md §3), through the host contract
// (host.h): before the host's opaque pass it renders the light slices (medium optical depth from
// each light, which also shadows the meshes); after it, the medium itself in the chosen mode into
// an offscreen layer the host composes over its scene.
//
// Does not: simulate (emitters fill the ParticleSet), own a GL context, or know any host's ECS,
// scene or renderer.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "nimbus/base/aabb.h"
#include "nimbus/gpu/frame_graph.h"
#include "nimbus/gpu/texture_pool.h"
#include "nimbus/gpu/view.h"
#include "nimbus/media/host.h"
#include "nimbus/media/graph_frame.h"
#include "nimbus/media/particle_set.h"

namespace nimbus::media {

// `billboards` is the yardstick a typical engine ships (lit sprites, no volumetric shadows): a
// measured baseline for `sandbox bench`, not a feature to tune.
// `raymarch` (seed 002) voxelises the particles and ray-marches the grid per pixel.
enum class MediaMode { Particles, Blocks, Billboards, Raymarch };
inline constexpr int kDefaultRaymarchSteps = 128;

// How blocks mode shades the blocks where a mesh is seen inside the medium (planning/block_classification.h
// blocksShadedExactly): exactly is at up to 16 points placed by their own particles, with the
// compositing order of overlapping blocks corrected; smoothly is at two points of each block's
// depth profile, as everywhere else.
enum class BlockShading : std::uint8_t {
    Smooth,  // smoothly everywhere: fastest, but can show a seam (docs/design-notes.md)
    Seam,    // exactly near the texels where a mesh lies among the particles, smoothly elsewhere
    Exact,   // exactly over those blocks' whole rectangles
};

enum class SliceDeposit : std::uint8_t { Off, On, Auto };

// Where `particles` mode evaluates each particle's light (the source J of DESIGN.md §2).
enum class ParticleLighting : std::uint8_t {
    Fragment,       // per fragment, with every correction: the exact tier
    Particle,       // per particle at five rays through its billboard, J linear across it; light
                    // at each ray's shading point (phase, smooth mesh shadow, slices' transmittance)
    ParticleExact,  // as Particle, each ray shaded as Fragment shades a pixel
};

// Parses "particles", "blocks", "billboards" or "raymarch"; throws InputError naming the option for anything else.
MediaMode parseMediaMode(const std::string& text, const std::string& origin = "--mode");
const char* mediaModeName(MediaMode mode);

// Zero values take the defaults noted.
struct MediaRenderSettings {
    MediaMode mode = MediaMode::Particles;
    int slices = 0;            // per light view; 0: chosen from the medium (see slice_plan.h), else 4..32
    int sliceResolution = 0;   // texels per side of a slice; 0: 256
    float sliceTexelsPerRadius = 0.0f;  // > 0: the resolution instead puts this many texels across the
                                        // median particle's radius (slice_plan.h sliceResolutionFor)
    // Slices as one float per particle and slab, then a running sum (the same values as the exact
    // pass within float rounding); auto: unless a lamp's views are among them.
    SliceDeposit sliceDeposit = SliceDeposit::Off;
    ParticleLighting lighting = ParticleLighting::Fragment;  // particles mode
    // With per-particle lighting: shade a frame per fragment after all where a lamp lies inside the
    // medium (lampInsideMedium). Around it 1/d² peaks across overlapping particles, and how much of
    // each lies in front of the lamp decides what the compositing order gets wrong, which only the
    // exact tier's lamp neighbourhoods correct (docs/design-notes.md).
    bool exactNearLamps = false;
    bool softParticles = true; // clip each particle's kernel at the opaque surface (off: billboard plane test)
    bool layerLight = true;    // particles mode: integrate the light's transmittance over each particle's layer
                               // (off: take it at one point: faster (docs/PERFORMANCE.md), less exact for
                               // dense particles)
    int blocks = 0;            // blocks mode: block count; 0: automatic (block_partition.h)
    float impostorScale = 0.0f;  // blocks mode: impostor texels per covered pixel; 0: 0.5
    bool instancing = false;   // blocks mode: one block prototype instanced at every block (seed 000 §2's b + N/b)
    BlockShading blockShading = BlockShading::Seam;  // blocks mode: where a mesh is seen in the medium
    int voxels = 0;            // raymarch mode: voxels along the grid's longest side; 0: from the particle size
    int raymarchSteps = 0;     // raymarch mode: most samples per ray; 0: kDefaultRaymarchSteps
    float mediaScale = 0.0f;   // resolution of the media pass relative to the frame (1, 0.5, 0.25); 0: 1
    bool mediaScaleAuto = false;  // automaticMediaScale: ½ to ¼ where the particles cover the image more than kHalfScaleCoverage times
                                  // over (the half-resolution pass then pays for its upsampling) and no
                                  // lamp lies among them (its peak is pixels wide), else 1
    float upsampleThreshold = 0.0f;  // relative depth difference the upsampler treats as an edge; 0: 0.2 (common/upsample.glsl)
};

// The settings with each zero field that stands for a value given it (sliceResolution 256,
// impostorScale 0.5, mediaScale 1, upsampleThreshold 0.2); where zero means "choose" (slices,
// blocks) it stays. MediaRenderer::prepare applies it, so a host may pass {} or only what it sets.
MediaRenderSettings withDefaults(MediaRenderSettings settings);

struct MediaFrameStats {
    std::size_t particles = 0;
    int slices = 0;            // per light view, this frame
    int sliceResolution = 0;   // texels per side, this frame
    int sliceViews = 0;        // light views that got slices
    int blocks = 0;            // blocks mode: blocks this frame
    std::size_t lampSliceParticles = 0;  // blocks mode: particles the lamps' slices take one by one (block_partition.h)
    int exactlyShadedBlocks = 0;         // blocks mode: blocks shaded exactly where a mesh is seen in the medium
                                         // (block_shading=seam: near the seam only)
    glm::ivec2 impostorAtlas{0};  // blocks mode: the camera's impostor atlas size
    glm::ivec3 voxels{0};         // raymarch mode: the grid's size
    float mediaScale = 1.0f;      // the media target's resolution relative to the frame, this frame
    bool exactLighting = false;   // particles mode: shaded per fragment this frame (exactNearLamps included)
    bool constantSource = false;  // per-particle lighting from one ray per particle (kConstantSplatPixels)
};

class LightSlicePass;
class ParticlePass;
class ParticleGpuBuffer;
class BlockGpuBuffers;
class BlockImpostorRenderer;
class BlockCompositePass;
class BlockSlicePass;
class BlockLampSlicePass;
class MediaDepthUsedPass;
class ParticleLightingPass;
class LightSliceDepositPass;
class SplatFloor;
class FrameBlocks;
struct ImmediateFrame;
class BillboardPass;
class RaymarchPass;
class LightSlicePrefixPass;
class ParticleSplatPass;
struct BlockFrame;
struct SliceView;
struct MediaTarget;
struct BlockViewPlan;
struct ImpostorView;

class MediaRenderer final {
public:
    MediaRenderer();
    ~MediaRenderer();
    MediaRenderer(const MediaRenderer&) = delete;
    MediaRenderer& operator=(const MediaRenderer&) = delete;

    // The medium to draw this frame. Keeps a reference: `particles` must outlive the frame.
    void prepare(const ParticleSet& particles, const MediaRenderSettings& settings);
    // World bounds of the particles: a host's shadow maps must cover them too.
    Aabb bounds() const { return bounds_; }
    // Whether this frame's settings read HostFrame::occluders (blocks mode); a host may skip them otherwise.
    bool readsOccluders() const { return settings_.mode == MediaMode::Blocks; }

    // In a host's frame graph (graph_frame.h): the light slices before the opaque pass, the medium after it.
    void addLightSlices(gpu::FrameGraph& graph, GraphFrame& frame);
    void addMedia(gpu::FrameGraph& graph, GraphFrame& frame);

    // For hosts without a frame graph: each call runs its passes now on a graph of the plugin's own.
    // Call both every frame, in this order; their results stay valid until the same call next frame.
    LightSlices renderLightSlices(const HostFrame& frame, gpu::PassTimer* timer = nullptr);
    MediaLayer renderMedia(const HostFrame& frame, gpu::PassTimer* timer = nullptr);

    const MediaFrameStats& stats() const { return stats_; }
    // The MediaSliceViews uniform block's buffer (LightSlices::views), for graph hosts. 0 before the first frame.
    GLuint sliceViewsBlock() const;

    // The splat floor of the last rendered frame's particles seen through `view` (splat_floor.h):
    // median ms of `repeats` GPU-synchronised draws. 0 before anything was drawn.
    double measureSplatFloor(const gpu::View& view, int repeats = 20);

private:
    void planTarget(const GraphFrame& frame);
    void partitionBlocks(const GraphFrame& frame);
    void planBlockCamera(const GraphFrame& frame);
    void addUploadPass(gpu::FrameGraph& graph, GraphFrame& frame);
    int planSliceViews(const GraphFrame& frame, std::vector<SliceView>& views, std::vector<glm::ivec2>& perLight);
    // `notDrawn`: per block, 1 where this view leaves its tile out (planBlockView).
    BlockViewPlan planFor(const ImpostorView& view, const glm::dvec3& origin, const std::vector<std::uint8_t>& notDrawn) const;

    const ParticleSet* particles_ = nullptr;
    MediaRenderSettings settings_;
    Aabb bounds_;
    std::unique_ptr<FrameBlocks> blocks_;
    std::unique_ptr<MediaTarget> target_;  // this frame's media target (planTarget)
    double coverage_ = 0.0;                // how many times over the billboards cover the image
    std::unique_ptr<ImmediateFrame> immediate_;  // renderLightSlices/renderMedia's graph state
    MediaFrameStats stats_;
    // GPU objects exist only once something is drawn ("model only what a scene needs").
    std::unique_ptr<ParticleGpuBuffer> buffer_;
    std::unique_ptr<LightSlicePass> slicePass_;
    std::unique_ptr<LightSliceDepositPass> depositPass_;
    std::unique_ptr<LightSlicePrefixPass> prefixPass_;
    std::unique_ptr<ParticlePass> particlePass_;
    std::unique_ptr<ParticleLightingPass> lightingPass_;
    std::unique_ptr<ParticleSplatPass> splatPass_;
    std::unique_ptr<BlockFrame> blockFrame_;  // blocks mode: this frame's partition and impostor plans
    std::unique_ptr<BlockGpuBuffers> blockBuffers_;
    std::unique_ptr<BlockImpostorRenderer> impostorRenderer_;
    std::unique_ptr<BlockCompositePass> blockCompositePass_;
    std::unique_ptr<BlockSlicePass> blockSlicePass_;
    std::unique_ptr<BlockLampSlicePass> lampSlicePass_;
    std::unique_ptr<MediaDepthUsedPass> depthUsedPass_;
    std::unique_ptr<SplatFloor> splatFloor_;
    std::unique_ptr<BillboardPass> billboardPass_;
    std::unique_ptr<RaymarchPass> raymarchPass_;
};

// The particles' billboards on screen, estimated on the CPU: how many times over they cover the
// image (Σ billboard area / image area, each clipped to the screen: what the splat floor pays for),
// and their half size in pixels, weighted by that area.
struct SplatFootprint {
    double coverage = 0.0;
    double radiusPixels = 0.0;
};
SplatFootprint splatFootprint(const ParticleSet& particles, const gpu::View& view);

// media_scale=auto: 1 unless the billboards cover the image more than kHalfScaleCoverage times
// over (fill dominates) and no lamp lies among them; then as low as keeps kAutoScaleRadiusTexels
// across a typical billboard's half size, within [¼, ½]. The kernel is smooth over a billboard,
// so the depth-aware upsampling loses next to nothing there (docs/design-notes.md).
float automaticMediaScale(const SplatFootprint& footprint, bool lampAmongParticles);
inline constexpr double kHalfScaleCoverage = 2.5;
inline constexpr double kAutoScaleRadiusTexels = 8.0;
// Below this many billboard pixels per particle, per-particle lighting takes one ray per particle:
// a fit across them has nothing to follow (docs/design-notes.md).
inline constexpr double kConstantSplatPixels = 2.0;

// Whether a point or spot light lies inside `bounds` (the particles').
bool lampAmongParticles(const std::vector<Light>& lights, const Aabb& bounds);

// Whether a point or spot light lies inside a particle that takes more than a tenth of a ray
// through its centre (a column over kLampMediumColumn): MediaRenderSettings::exactNearLamps.
inline constexpr double kLampMediumColumn = 0.1;
bool lampInsideMedium(const ParticleSet& particles, const std::vector<Light>& lights);

// Whether the eye (an orthographic camera's plane) lies inside some particle's sphere.
bool eyeInsideMedium(const ParticleSet& particles, const gpu::View& view);

// World bounds of the particle spheres.
Aabb particleBounds(const ParticleSet& particles);

}  // namespace nimbus::media
