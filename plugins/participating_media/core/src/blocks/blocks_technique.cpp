#include "blocks/blocks_technique.h"

#include <algorithm>
#include <numeric>

#include "blocks/block_composite_edges_pass.h"
#include "blocks/block_composite_pass.h"
#include "blocks/block_gpu_buffers.h"
#include "blocks/block_impostor_cache.h"
#include "blocks/block_impostor_pass.h"
#include "blocks/block_impostor_renderer.h"
#include "blocks/block_lamp_slice_pass.h"
#include "blocks/block_light_impostor_pass.h"
#include "blocks/block_slice_pass.h"
#include "common/lamp_neighbourhood.h"
#include "common/shared_frame.h"
#include "nimbus/base/settings.h"
#include "nimbus/media/block_partition.h"
#include "nimbus/media/medium_footprint.h"
#include "planning/block_classification.h"
#include "planning/block_view_plan.h"

namespace nimbus::media {
namespace {

constexpr int kMaxAtlasSize = 4096;

const SettingField<BlocksSettings> kBlocksFields[] = {
    // At the most, each block's impostor keeps a 16x16 tile of the largest atlas.
    {{.key = "blocks",
      .help = "number of particle blocks (a block holds at least one particle: fewer particles make as many blocks)",
      .type = SettingType::Integer,
      .min = 1,
      .max = (kMaxAtlasSize / 16) * (kMaxAtlasSize / 16),
      .defaultValue = "round(2 sqrt(particles)), more in optically thick media or around a lamp inside them"},
     &setInteger<&BlocksSettings::blocks>},
    {{.key = "impostor_scale",
      .help = "impostor texels per covered pixel; auto: as few as keep 6 texels across a typical billboard's half size, "
              "1/4 to 1/2",
      .type = SettingType::Number,
      .min = 0.05,
      .max = 4.0,
      .words = {"auto"},
      .defaultValue = "0.5 (balanced and fast: auto)"},
     &setNumberOrAuto<&BlocksSettings::impostorScale, &BlocksSettings::impostorScaleAuto>},
    {{.key = "instancing", .help = "build the cloud from one block prototype instanced at every block", .type = SettingType::Boolean,
      .defaultValue = "off"},
     &setBoolean<&BlocksSettings::instancing>},
    {{.key = "block_shading",
      .help = "where a mesh is seen in the medium: seam shades the blocks from their particles with the compositing order "
              "corrected near the mesh, smooth is faster there but the mesh can show a seam, exact is seam over those blocks' "
              "whole rectangles (slowest)",
      .type = SettingType::Choice,
      .words = {"seam", "smooth", "exact"},
      .defaultValue = "seam (fast: smooth)"},
     &setChoice<&BlocksSettings::blockShading>},
    {{.key = "block_lighting",
      .help = "where the blocks' smooth shading is evaluated: at every pixel a block covers, or once per two by two texels of "
              "its impostor, read back bilinearly (not near a point or spot light; block_shading's exact shading stays per pixel)",
      .type = SettingType::Choice,
      .words = {"pixel", "texel"},
      .defaultValue = "pixel (balanced and fast: texel)"},
     &setChoice<&BlocksSettings::lighting>,
     // An instance's tile is the prototype's, lit where the prototype stands.
     [](const BlocksSettings& s) { return !s.instancing; }},
    {{.key = "impostor_reuse",
      .help = "read the camera's block impostors and their light again in later frames while every block's direction from the "
              "eye turns by at most this many degrees, its size on screen changes by at most 10% and nothing but the camera "
              "moved or changed (0: render them every frame)",
      .type = SettingType::Number,
      .min = 0.0,
      .max = 10.0,
      .defaultValue = "0 (balanced and fast: 2)",
      .showsWith = kShowsWithMovingCamera},
     &setNumber<&BlocksSettings::reuseDegrees>,
     // An instance's tile is the prototype's, drawn every frame.
     [](const BlocksSettings& s) { return !s.instancing; }},
};

// What blocks mode keeps for one frame: the partition and the impostor layouts, which the passes'
// execute steps read after setup returns.
struct BlockFrame {
    BlockPartition partition;
    bool instanced = false;
    std::size_t prototype = 0;              // instancing: the block every block is drawn as
    std::vector<BlockViewPlan> lightPlans;  // one per slice view
    BlockViewPlan cameraPlan;
    std::vector<std::uint32_t> backToFront;
    std::vector<glm::uvec2> orderNeighbours;  // overlappingBlockLists
    std::vector<std::uint32_t> blockRankOf;   // per particle: its block's place in backToFront
    std::vector<std::uint8_t> wideFromLamps;        // per block: the lamps' slices take its particles one by one
    std::vector<std::uint32_t> lampSliceParticles;  // those particles
    std::vector<std::uint8_t> builds;               // per block: the composite variant (kBlockExactCut, ...)
    ReuseDecision reuse;                            // what this frame reads again from the cache
    bool keep = false;                              // this frame renders what it does not reuse into the cache
};

class BlocksTechnique final : public MediaTechnique {
public:
    bool readsOccluders() const override { return true; }
    void forgetFrames() override {
        if (cache_) cache_->forget();
    }

    // This frame's partition and which blocks the lamps' slices take one by one.
    void plan(TechniqueFrame& frame, const GraphFrame& context) override {
        own_ = techniqueSettings<BlocksSettings>(*frame.settings);
        if (own_.impostorScaleAuto) own_.impostorScale = automaticImpostorScale(frame.shared->radiusTexels);
        if (own_.impostorScale <= 0.0f) own_.impostorScale = 0.5f;
        if (!buffers_) buffers_ = std::make_unique<BlockGpuBuffers>();
        const std::vector<glm::dvec3> lamps = lampPositions(context.host.lights);
        frame_.partition = partitionIntoBlocks(*frame.particles, own_.blocks, lamps);
        frame_.instanced = own_.instancing;
        frame_.prototype = choosePrototype(frame_.partition);
        frame_.lightPlans.clear();
        // An instance has no particles of its own to draw one by one.
        frame_.wideFromLamps = frame_.instanced ? std::vector<std::uint8_t>(frame_.partition.blocks.size(), 0)
                                                : blocksSeenWideFromLamps(frame_.partition, lamps);
        frame_.lampSliceParticles.clear();
        for (std::size_t b = 0; b < frame_.partition.blocks.size(); ++b) {
            if (frame_.wideFromLamps[b] == 0) continue;
            const Block& block = frame_.partition.blocks[b];
            frame_.lampSliceParticles.insert(frame_.lampSliceParticles.end(), frame_.partition.order.begin() + block.first,
                                             frame_.partition.order.begin() + block.first + block.count);
        }
        frame.report("blocks", static_cast<long long>(frame_.partition.blocks.size()));
        frame.report("impostor_scale", static_cast<double>(own_.impostorScale));
        frame.report("lamp_slice_particles", static_cast<long long>(frame_.lampSliceParticles.size()));
    }

    // Everything blocks mode draws from this frame, uploaded before its first draw.
    void upload(TechniqueFrame& frame, const GraphFrame& context) override {
        if (frame_.instanced) buffers_->uploadItems(frame_.partition, frame_.prototype);
        else buffers_->uploadItems(frame_.partition);
        std::vector<const BlockViewPlan*> plans{&frame_.cameraPlan};
        for (const BlockViewPlan& plan : frame_.lightPlans) plans.push_back(&plan);
        buffers_->uploadTileSets(plans);
        buffers_->uploadDrawOrder(frame_.backToFront);
        buffers_->uploadOrderNeighbours(frame_.orderNeighbours);
        buffers_->uploadLampSliceParticles(frame_.lampSliceParticles);
        if (!anyLamp(context.host.lights)) return;
        frame_.blockRankOf.assign(frame.particles->size(), 0u);
        double largestBlock = 0.0;  // a lamp's 1/d² varies across a block within about its size of the lamp
        for (std::size_t r = 0; r < frame_.backToFront.size(); ++r) {
            const Block& block = frame_.partition.blocks[frame_.backToFront[r]];
            largestBlock = std::max(largestBlock, block.radius);
            for (std::uint32_t k = block.first; k < block.first + block.count; ++k)
                frame_.blockRankOf[frame_.partition.order[k]] = static_cast<std::uint32_t>(r);
        }
        frame.shared->buffer->uploadLampNeighbourhoods(*frame.particles, context.host.lights, frame_.blockRankOf, LampsListed::All,
                                                       largestBlock);
    }

    // Planned with the light slices, so everything blocks mode draws is uploaded before its first
    // draw whether the host runs one graph or two.
    void addLightSlices(gpu::FrameGraph& graph, GraphFrame& context, TechniqueFrame& frame) override {
        planCamera(frame, context);
        const SharedFrame& shared = *frame.shared;
        const std::vector<SliceView>& views = shared.sliceViews;
        if (views.empty()) return;
        for (const SliceView& v : views) {
            const ImpostorView view{v.view.view, v.view.viewProjection, v.view.perspective, v.lightOrigin, 0.0f,
                                    glm::ivec2(shared.sliceResolution)};
            // A lamp's views leave out the blocks whose particles its slices take one by one.
            const std::vector<std::uint8_t> none;
            frame_.lightPlans.push_back(planFor(view, context.host.camera.origin, view.perspective ? frame_.wideFromLamps : none));
        }
        if (frame_.reuse.light) {  // impostor_reuse: nothing the light slices hold has changed
            context.slices = graph.importTexture("light_slices", cache_->slices());
            return;
        }
        if (!impostors_) impostors_ = std::make_unique<BlockImpostorRenderer>();
        if (!slicePass_) slicePass_ = std::make_unique<BlockSlicePass>();
        const BlockLightImpostors light = addBlockLightImpostorPass(graph, frame_.lightPlans, *buffers_, *shared.buffer, *impostors_);
        const gpu::TextureDesc slices = BlockSlicePass::sliceDesc(views, shared.sliceResolution);
        context.slices = slicePass_->add(graph, views, frame_.lightPlans, light, slices, *buffers_, frame_.keep ? &cache_->keepSlices(slices) : nullptr);
        const bool lampViews = std::any_of(views.begin(), views.end(), [](const SliceView& v) { return v.view.perspective; });
        if (lampViews && !frame_.lampSliceParticles.empty()) {
            if (!lampSlicePass_) lampSlicePass_ = std::make_unique<BlockLampSlicePass>();
            context.slices = lampSlicePass_->add(graph, context.slices, views, shared.sliceResolution, *buffers_, *shared.buffer);
        }
    }

    gpu::ResourceHandle addMedia(gpu::FrameGraph& graph, GraphFrame& context, TechniqueFrame& frame) override {
        if (!impostors_) impostors_ = std::make_unique<BlockImpostorRenderer>();
        if (!compositePass_) compositePass_ = std::make_unique<BlockCompositePass>();
        const SharedFrame& shared = *frame.shared;
        BlockImpostorAtlas atlas;
        LitAtlasSource lit;
        if (frame_.reuse.camera == ReuseVerdict::Reused) {
            atlas = cache_->importAtlas(graph);
            lit.reused = graph.importTexture("block_impostor_lit", cache_->litTexture());
        } else {
            const BlockImpostorAtlas kept = frame_.keep ? cache_->importAtlas(graph) : BlockImpostorAtlas{};
            atlas = addBlockImpostorPass(graph, frame_.cameraPlan, *buffers_, *shared.buffer, *impostors_, frame_.keep ? &kept : nullptr);
            if (frame_.keep) lit.keep = &cache_->litTexture();
        }
        edgeRect_ = frame.settings->upsampleOnly ? glm::ivec4(0)
                                                 : meshEdgeRect(context.host.occluders, *frame.particles, context.host.camera, shared.target.size);
        return compositePass_->add(graph, context, {atlas, lit}, frame_.backToFront, frame_.builds,
                                   own_.blockShading == BlockShading::Seam, *buffers_, *shared.buffer, shared.target);
    }

    // Mixed resolution where a mesh enters the particles: the blocks composited again there.
    glm::ivec4 edgeRect() const override { return edgeRect_; }
    gpu::ResourceHandle addEdges(gpu::FrameGraph& graph, GraphFrame& context, TechniqueFrame& frame, const EdgeTarget& edges) override {
        return addBlockCompositeEdges(graph, context, *compositePass_, *buffers_, *frame.shared->buffer, edges);
    }

private:
    BlockViewPlan planFor(const ImpostorView& view, const glm::dvec3& origin, const std::vector<std::uint8_t>& notDrawn) const {
        return frame_.instanced
                   ? planInstancedBlockView(frame_.partition, frame_.prototype, view, origin, own_.impostorScale, kMaxAtlasSize)
                   : planBlockView(frame_.partition, view, origin, own_.impostorScale, kMaxAtlasSize, notDrawn);
    }

    void planCamera(TechniqueFrame& frame, const GraphFrame& context);
    void planReuse(TechniqueFrame& frame, const GraphFrame& context);
    void sortBackToFront(const gpu::View& v);

    BlocksSettings own_;
    BlockFrame frame_;
    std::unique_ptr<BlockGpuBuffers> buffers_;  // each made when first needed
    std::unique_ptr<BlockImpostorRenderer> impostors_;
    std::unique_ptr<BlockCompositePass> compositePass_;
    std::unique_ptr<BlockSlicePass> slicePass_;
    std::unique_ptr<BlockLampSlicePass> lampSlicePass_;
    std::unique_ptr<BlockImpostorCache> cache_;  // impostor_reuse: made when first on
    glm::ivec4 edgeRect_{0};  // this frame's, as addMedia planned it
};

// Back to front by distance from the eye to the block centre (depth along the axis when orthographic).
void BlocksTechnique::sortBackToFront(const gpu::View& v) {
    std::vector<double> keys(frame_.partition.blocks.size());
    for (std::size_t b = 0; b < keys.size(); ++b) {
        const glm::dvec3 d = frame_.partition.blocks[b].centre - v.origin;
        keys[b] = v.orthographic ? glm::dot(d, v.forward) : glm::length(d);
    }
    frame_.backToFront.resize(keys.size());
    std::iota(frame_.backToFront.begin(), frame_.backToFront.end(), 0u);
    std::stable_sort(frame_.backToFront.begin(), frame_.backToFront.end(), [&](std::uint32_t a, std::uint32_t b) { return keys[a] > keys[b]; });
}

// From the camera: the impostor plan, the back-to-front order and how each block is composited.
void BlocksTechnique::planCamera(TechniqueFrame& frame, const GraphFrame& context) {
    const gpu::View& v = context.host.camera;
    const ImpostorView view{v.view, v.viewProjection, !v.orthographic, glm::vec3(0.0f), v.znear, frame.shared->target.size};
    frame_.cameraPlan = planFor(view, v.origin, {});
    for (std::size_t b = 0; b < frame_.cameraPlan.tiles.size(); ++b)
        frame_.cameraPlan.tiles[b].lampSlices.x = frame_.wideFromLamps[b] != 0 ? 1.0f : 0.0f;
    sortBackToFront(v);
    const std::vector<OccluderBox>& meshes = context.host.occluders;
    frame_.builds = blocksNearMeshes(frame_.partition, meshes);
    frame_.orderNeighbours.clear();
    int exactlyShaded = 0;
    if (!frame_.instanced) {  // an instance's particles are not listed
        const std::vector<std::uint8_t> own = blocksOfUnresolvedParticles(frame_.partition, *frame.particles, context.sliceViews, v.origin);
        const std::vector<std::uint8_t> exact = own_.blockShading != BlockShading::Smooth
                                                    ? blocksShadedExactly(frame_.partition, meshes, frame_.cameraPlan, v)
                                                    : std::vector<std::uint8_t>(frame_.builds.size(), 0);
        for (std::size_t b = 0; b < frame_.builds.size(); ++b)
            frame_.builds[b] = static_cast<std::uint8_t>(frame_.builds[b] | (own[b] ? kBlockOwnParticles : 0) | (exact[b] ? kBlockExactShading : 0));
        if (std::find(exact.begin(), exact.end(), std::uint8_t{1}) != exact.end())
            frame_.orderNeighbours = overlappingBlockLists(frame_.partition, frame_.backToFront);
        exactlyShaded = static_cast<int>(std::count(exact.begin(), exact.end(), std::uint8_t{1}));
    }
    // A block takes its light from the texels wherever it is shaded smoothly: off the seam when
    // block_shading=seam draws it exactly near a mesh, and with block_shading=smooth also where a
    // mesh cuts it (its opacity is cut per pixel, its light is the whole column's). Not near a
    // lamp (wideFromLamps): a ray's light peaks as it passes the lamp, sharper than two texels.
    int litBlocks = 0;
    const bool seamOnly = own_.blockShading == BlockShading::Seam;
    const bool lit = own_.lighting == BlockLighting::Texel && !frame_.instanced;
    for (std::size_t b = 0; b < frame_.builds.size(); ++b) {
        std::uint8_t& build = frame_.builds[b];
        const bool exact = (build & kBlockExactShading) != 0;
        if (!lit || (exact && !seamOnly) || frame_.wideFromLamps[b] != 0) continue;
        build = static_cast<std::uint8_t>(build | kBlockLitImpostor);
        ++litBlocks;
    }
    frame.report("texel_lit_blocks", static_cast<long long>(litBlocks));
    frame.report("exactly_shaded_blocks", static_cast<long long>(exactlyShaded));
    planReuse(frame, context);
}

// impostor_reuse: read the cache's atlas again through this view, or render this frame's into it.
// Off, instanced, with a volume or with meshes the host does not box, every frame renders its own.
void BlocksTechnique::planReuse(TechniqueFrame& frame, const GraphFrame& context) {
    frame_.reuse = {};
    frame_.keep = false;
    if (!(own_.reuseDegrees > 0.0f) || frame_.instanced || !frame.volumes->empty() || !context.host.occludersComplete) {
        if (cache_) cache_->forget();
        return;
    }
    if (!cache_) cache_ = std::make_unique<BlockImpostorCache>();
    const gpu::View& v = context.host.camera;
    ImpostorSources sources{.lights = context.host.lights,
                            .occluders = context.host.occluders,
                            .ambient = context.host.ambient,
                            .multiple = context.multiple,
                            .target = frame.shared->target.size,
                            .shared = *frame.settings,
                            .own = own_};
    const WorldView view{.origin = v.origin,
                         .viewProjection = glm::dmat4(v.viewProjection),
                         .forward = v.forward,
                         .perspective = !v.orthographic,
                         .znear = v.znear};
    frame_.reuse = cache_->decide(*frame.particles, std::move(sources), frame_.builds, frame_.partition, view, {.degrees = own_.reuseDegrees}, frame_.cameraPlan);
    frame_.keep = true;
    frame.report("impostors_reused", frame_.reuse.camera == ReuseVerdict::Reused);
    frame.report("light_slices_reused", frame_.reuse.light);
}

// The automatic block count and counts around it, impostor resolution, slices, instancing, media
// scale, and the shading where a mesh is seen inside (the same frame as `blocks` without one).
std::vector<BenchRow> blockBenchRows(const ParticleSet& particles, const std::vector<glm::dvec3>& lamps) {
    const int autoBlocks = automaticBlockCount(particles, lamps);
    std::vector<BenchRow> rows{{"blocks", {{"mode", "blocks"}}}};
    for (const int blocks : {std::max(1, autoBlocks / 4), std::max(1, autoBlocks / 2), autoBlocks * 2, autoBlocks * 4}) {
        if (blocks == autoBlocks || static_cast<std::size_t>(blocks) > particles.size()) continue;
        rows.push_back({"blocks blocks=" + std::to_string(blocks), {{"mode", "blocks"}, {"blocks", std::to_string(blocks)}}});
    }
    for (const char* scale : {"0.25", "1"})
        rows.push_back({std::string("blocks impostor_scale=") + scale, {{"mode", "blocks"}, {"impostor_scale", scale}}});
    rows.push_back({"blocks slices=8", {{"mode", "blocks"}, {"slices", "8"}}});
    rows.push_back({"blocks instancing", {{"mode", "blocks"}, {"instancing", "on"}}});
    rows.push_back({"blocks media_scale=0.5", {{"mode", "blocks"}, {"media_scale", "0.5"}}});
    rows.push_back({"blocks block_shading=smooth", {{"mode", "blocks"}, {"block_shading", "smooth"}}});
    rows.push_back({"blocks block_shading=exact", {{"mode", "blocks"}, {"block_shading", "exact"}}});
    return rows;
}

}  // namespace

BlocksSettings BlocksSettings::forTier(QualityTier tier) {
    BlocksSettings s;
    if (tier != QualityTier::Exact) s.lighting = BlockLighting::Texel;
    if (tier != QualityTier::Exact) s.reuseDegrees = 2.0f;
    // A large billboard's kernel is smooth over many pixels: a quarter of the texels keep it
    // (cumulus at 1280x720 moved by 0.18%, docs/design-notes.md).
    if (tier != QualityTier::Exact) s.impostorScaleAuto = true;
    // At fast's reduced resolution the exact seam bought no band error (docs/design-notes.md).
    if (tier == QualityTier::Fast) s.blockShading = BlockShading::Smooth;
    return s;
}

TechniqueEntry blocksTechnique() {
    return {.name = "blocks",
            .help = "impostors of particle blocks composited back to front, cut where a mesh reaches them",
            .sliceCrops = true,
            .edges = true,
            // Not lampPeaks: campfire fast at ¼ erred 6.2% against 3.1% at full resolution, over the
            // lamp-lit impostors, not only at the peak.
            .withinMedium = true,
            .settings = specsOf(kBlocksFields),
            // Where a mesh reaches into the medium, fast keeps balanced's slice detail and twice fast's
            // slices: the light the mesh cuts there is most of the seam band's error, and blocks
            // afford it (docs/design-notes.md).
            .sharedDefaults =
                [](MediaRenderSettings& s, QualityTier tier) {
                    if (tier != QualityTier::Fast) return;
                    s.slicesNearMeshes = 32;
                    s.sliceTexelsPerRadiusNearMeshes = 4.0f;
                },
            .read = readerOf(kBlocksFields),
            .idle = idleOf(kBlocksFields),
            .create = [] { return std::make_unique<BlocksTechnique>(); },
            .benchRows = blockBenchRows,
            .scalingBench = true};
}

}  // namespace nimbus::media
