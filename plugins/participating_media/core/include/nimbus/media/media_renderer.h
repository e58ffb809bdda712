#pragma once
// The participating media in the real-time frame (docs/design.md §3), through the host contract
// (host.h): before the host's opaque pass it renders the light slices (medium optical depth from
// each light, which also shadows the meshes); after it, the medium itself in the chosen mode into
// an offscreen layer the host composes over its scene.
//
// The renderer plans what every mode shares (the particle buffer, the uniform blocks, the media
// target, the light slice views, the upsampling) and calls the frame's technique (technique.h)
// for the rest. It names no mode: the technique table does.
//
// Does not: simulate (emitters fill the ParticleSet), own a GL context, or know any host's ECS,
// scene or renderer.
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "nimbus/base/aabb.h"
#include "nimbus/gpu/frame_graph.h"
#include "nimbus/gpu/view.h"
#include "nimbus/media/graph_frame.h"
#include "nimbus/media/host.h"
#include "nimbus/media/media_settings.h"
#include "nimbus/media/medium_footprint.h"
#include "nimbus/media/particle_set.h"
#include "nimbus/media/technique.h"
#include "nimbus/media/volume.h"

namespace nimbus::media {

struct MediaFrameStats {
    std::size_t particles = 0;
    int slices = 0;            // per light view, this frame
    int sliceResolution = 0;   // texels per side, this frame
    int sliceViews = 0;        // light views that got slices
    int slicesCropped = 0;     // of them, crops over where meshes reach into the medium (slice_crop)
    float mediaScale = 1.0f;   // the media target's resolution relative to the frame, this frame
    std::string mode;          // the technique that drew the frame
    bool multipleScattering = false;  // the multiple model's grid was read (not: single, or negligible)
    float rescatter = 0.0f;    // the multiple model: the share of first-scattered light that scatters again ("negligible" below 1%)
    double scatteringSolveMs = 0.0;  // the multiple model: CPU time of its grid's solve this frame (0: the last frame's answer kept)
    bool scatteringWarm = false;     // that solve started from the last frame's answer (scattering_warm_sweeps)
    std::vector<TechniqueStat> technique;  // what it reported (TechniqueStat)
    // A technique's figure as a number (a bool as 0 or 1); `fallback` when it reported none.
    double value(const std::string& key, double fallback = 0.0) const;
};

class ParticleGpuBuffer;
class MediaDepthUsedPass;
class MediaEdgeStencilPass;
class MediaSeamMarksPass;
class LightSliceIntervalsPass;
class SplatFloor;
struct ImmediateFrame;
struct SliceView;

class MediaRenderer final {
public:
    explicit MediaRenderer(TechniqueTable techniques = builtInTechniques());
    ~MediaRenderer();
    MediaRenderer(const MediaRenderer&) = delete;
    MediaRenderer& operator=(const MediaRenderer&) = delete;

    const TechniqueTable& techniques() const { return techniques_; }

    // The medium to draw this frame. Keeps a reference: `particles` and `volumes` must outlive the
    // frame. InputError when settings.mode names no technique of the table, or one that does not
    // draw volumes while there are some.
    void prepare(const ParticleSet& particles, const MediaRenderSettings& settings, const std::vector<Volume>* volumes = nullptr);
    // World bounds of the particles: a host's shadow maps must cover them too.
    Aabb bounds() const;
    // Whether this frame's technique reads HostFrame::occluders; a host may skip them otherwise.
    bool readsOccluders() const;
    // The next frame is drawn as if it were the first: nothing kept from earlier frames is read
    // again (a renderer handed to another scene or session; MediaTechnique::forgetFrames).
    void forgetFrames();

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
    float automaticScale(const GraphFrame& context, const SplatFootprint& footprint, glm::ivec4 medium, bool peaksRedrawn) const;
    SplatFootprint lampLitFootprint(SplatFootprint all, const std::vector<Light>& lights, const gpu::View& v) const;
    void addUploadPass(gpu::FrameGraph& graph, GraphFrame& frame);
    void planSliceViews(const GraphFrame& frame, std::vector<glm::ivec2>& perLight);
    void planScattering(GraphFrame& frame);  // the multiple-scattering model's environment grid
    MediaTechnique& technique(const TechniqueEntry& entry);  // made when first used
    [[noreturn]] void refuseVolumes(const TechniqueEntry& entry, const Volume& volume) const;

    TechniqueTable techniques_;
    std::map<std::string, std::unique_ptr<MediaTechnique>> made_;
    MediaTechnique* technique_ = nullptr;  // this frame's
    bool drawsOver_ = false;               // its entry's drawsOver
    const ParticleSet* particles_ = nullptr;
    const std::vector<Volume>* volumes_ = nullptr;
    std::vector<Volume> noVolumes_;
    MediaRenderSettings settings_;
    std::unique_ptr<SharedFrame> shared_;
    TechniqueFrame frame_;
    std::unique_ptr<ImmediateFrame> immediate_;  // renderLightSlices/renderMedia's graph state
    MediaFrameStats stats_;
    std::unique_ptr<MediaDepthUsedPass> depthUsedPass_;
    std::unique_ptr<MediaEdgeStencilPass> edgeStencilPass_;
    std::unique_ptr<MediaSeamMarksPass> seamMarksPass_;
    std::unique_ptr<LightSliceIntervalsPass> sliceIntervalsPass_;
    std::unique_ptr<SplatFloor> splatFloor_;
};

}  // namespace nimbus::media
