#pragma once
// A media mode is a technique: one implementation of MediaTechnique in its own folder, described
// by one TechniqueEntry in a TechniqueTable. The renderer (media_renderer.h) plans what every mode
// shares (the particle buffer, the uniform blocks, the media target, the light slice views) and
// calls the frame's technique; it names no mode. The table alone gives the modes' names to the
// command line, a scene's render.mode, `sandbox settings`, the schema, the editor and the errors.
//
// A technique provides:
//   plan            before the upload pass: what it draws this frame (blocks: the partition)
//   upload          inside the upload pass, after the particles: its own buffers
//   addLightSlices  the light slices towards every light, into GraphFrame::slices
//   addMedia        the medium into the media target; returns its colour
//   addEdges        optional, after addMedia into a reduced target: the medium again at full
//                   resolution, within edgeRect, where the upsampling meets another depth
// and its entry: name, help, its own setting declarations and reader, and a factory.
//
// Does not: own the particles or the host's resources, or outlive the renderer that made it.
#include <any>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include "nimbus/base/quality_tier.h"
#include "nimbus/base/setting_spec.h"
#include "nimbus/base/settings.h"
#include "nimbus/gpu/frame_graph.h"
#include "nimbus/media/graph_frame.h"
#include "nimbus/media/media_settings.h"
#include "nimbus/media/particle_set.h"
#include "nimbus/media/volume.h"

namespace nimbus::media {

struct SharedFrame;  // what every mode shares this frame (core/src/common/shared_frame.h)

// One figure a technique reports for a frame (`sandbox render --stats` writes it as media_<key>).
struct TechniqueStat {
    std::string key;
    std::variant<bool, long long, double> value;
};

// Where a technique draws the medium again at full resolution (MediaLayer::edges).
// Its texel t is the viewport's pixel rect.xy + t.
struct EdgeTarget {
    gpu::ResourceHandle color;    // RGBA32F, at least rect.zw texels: (0, 0, 0, 1) at the edges, alpha −1 elsewhere
    gpu::ResourceHandle stencil;  // D24S8, its size: stencil 1 at the edges, 0 elsewhere
    glm::ivec4 rect{0};           // x, y, width, height in the viewport's pixels
};

// The frame as a technique's calls see it.
struct TechniqueFrame {
    const ParticleSet* particles = nullptr;
    const std::vector<Volume>* volumes = nullptr;  // never null while a frame is drawn
    const MediaRenderSettings* settings = nullptr;
    SharedFrame* shared = nullptr;
    std::vector<TechniqueStat>* stats = nullptr;  // cleared each frame; the technique appends
    void report(std::string key, std::variant<bool, long long, double> value) const { stats->push_back({std::move(key), value}); }
};

class MediaTechnique {
public:
    virtual ~MediaTechnique() = default;
    virtual void plan(TechniqueFrame&, const GraphFrame&) {}
    virtual void upload(TechniqueFrame&, const GraphFrame&) {}
    virtual void addLightSlices(gpu::FrameGraph& graph, GraphFrame& context, TechniqueFrame& frame) = 0;
    virtual gpu::ResourceHandle addMedia(gpu::FrameGraph& graph, GraphFrame& context, TechniqueFrame& frame) = 0;
    // The pixels (x, y, width, height) within which what addMedia drew this frame is drawn again
    // at a reduced target's edges; width 0 (the default): none, the host upsamples them all.
    virtual glm::ivec4 edgeRect() const { return glm::ivec4(0); }
    // The same medium into `edges.color`, where `edges.stencil` is 1; returns the colour.
    virtual gpu::ResourceHandle addEdges(gpu::FrameGraph&, GraphFrame&, TechniqueFrame&, const EdgeTarget&) { return {}; }
    // Whether this frame reads HostFrame::occluders; a host may skip them otherwise.
    virtual bool readsOccluders() const { return false; }
    // Drops whatever earlier frames left for later ones to read again (blocks' impostor_reuse), so
    // the next frame is drawn as if it were the first.
    virtual void forgetFrames() {}
};

// A configuration `sandbox bench` sweeps: its row name and the settings it sets.
struct BenchRow {
    std::string name;
    std::vector<std::pair<std::string, std::string>> settings;
};

struct TechniqueEntry {
    std::string name;  // what --mode and render.mode take
    std::string help;  // what the mode is, in one line
    bool lightSlices = true;    // lit by the shared light slice views (the slice keys act in it)
    bool sliceDeposit = false;  // its slices honour slice_deposit
    bool sliceCrops = false;    // its lighting reads a light's slice crop (slice_crop acts in it)
    bool multipleScattering = true;  // draws the multiple-scattering model (the scattering keys act in it)
    bool volumes = false;            // draws volumes (volume.h); the other modes refuse a scene with one
    bool edges = false;              // may draw a reduced image's edges again (addEdges): mixed_resolution acts in it
    // With edges: a reduced target, with a point light's peak drawn again (MediaTarget::peak), errs
    // about as the full-resolution one, so media_scale=auto may reduce it with a lamp among the particles.
    bool lampPeaks = false;
    bool drawsOver = false;          // its full-resolution passes honour MediaTarget::over (blend over the host's output)
    // What addMedia draws lies within the particles' spheres and the volumes' boxes on screen
    // (SharedFrame::target.cover, which the technique widens where it reaches further): the host
    // composes only there. Off (a mode of your own, by default): the layer may fill the viewport.
    bool withinMedium = false;
    std::vector<SettingSpec> settings;  // its own keys (the table sets their `modes` to this name)
    // Its own tier defaults for shared keys, over the tier's and under any key that was set (the
    // shared keys' help says them). Null: the tier's.
    std::function<void(MediaRenderSettings&, QualityTier)> sharedDefaults;
    // Its typed settings for `tier` with every one of its keys that was set applied.
    std::function<std::any(const Settings&, QualityTier)> read;
    // Its keys that do not act with its settings as `read` gave them (SettingField::acts, e.g. a
    // key only per-fragment lighting reads) and the shared ones; a key set there is refused. Null:
    // they all act.
    std::function<std::vector<std::string>(const std::any&, const MediaRenderSettings&)> idle;
    std::function<std::unique_ptr<MediaTechnique>()> create;
    // Its rows of `sandbox bench`'s sweep for a scene's particles and lamps; none where empty.
    std::function<std::vector<BenchRow>(const ParticleSet&, const std::vector<glm::dvec3>& lamps)> benchRows;
    bool scalingBench = false;  // in `sandbox bench --scaling`'s particle-count sweep
};

// The modes a renderer offers, in the order users see them; the first is the default.
class TechniqueTable {
public:
    // Throws std::logic_error for a name already in the table or a key another mode declared.
    void add(TechniqueEntry entry);
    std::span<const TechniqueEntry> entries() const { return entries_; }
    const TechniqueEntry* find(const std::string& name) const;
    // The entry `name` names (empty: the first); InputError naming `origin` and listing the modes.
    const TechniqueEntry& at(const std::string& name, const std::string& origin = "--mode") const;
    std::vector<std::string> names() const;

private:
    std::vector<TechniqueEntry> entries_;
};

// TechniqueEntry::read for a settings struct S with a `static S forTier(QualityTier)`: the tier's
// struct with every one of `fields` that was set applied.
template <class S, std::size_t N>
std::function<std::any(const Settings&, QualityTier)> readerOf(const SettingField<S> (&fields)[N]) {
    return [&fields](const Settings& settings, QualityTier tier) -> std::any { return readFields<S>(settings, fields, S::forTier(tier)); };
}

// TechniqueEntry::idle for the same fields: the keys whose `acts` is false for the read settings.
template <class S, std::size_t N>
std::function<std::vector<std::string>(const std::any&, const MediaRenderSettings&)> idleOf(const SettingField<S> (&fields)[N]) {
    return [&fields](const std::any& read, const MediaRenderSettings&) { return idleKeys(fields, std::any_cast<const S&>(read)); };
}

// particles, blocks, raymarch, sheets and billboards (core/src/frame/technique_table.cpp).
TechniqueTable builtInTechniques();

}  // namespace nimbus::media
