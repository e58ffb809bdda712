#include "nimbus/media/media_renderer.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "raymarch/raymarch_pass.h"
#include "raymarch/voxel_grid.h"
#include "billboards/billboard_pass.h"
#include "blocks/block_composite_pass.h"
#include "blocks/block_impostor_pass.h"
#include "blocks/block_lamp_slice_pass.h"
#include "blocks/block_light_impostor_pass.h"
#include "blocks/block_slice_pass.h"
#include "particles/particle_lighting_pass.h"
#include "particles/particle_pass.h"
#include "particles/particle_splat_pass.h"
#include "planning/block_classification.h"
#include "slices/light_slice_deposit_pass.h"
#include "slices/light_slice_pass.h"
#include "slices/light_slice_prefix_pass.h"
#include "upsample/media_depth_used_pass.h"
#include "nimbus/base/error.h"
#include "nimbus/media/slice_plan.h"
#include "common/frame_blocks.h"
#include "frame/immediate_frame.h"
#include "common/particle_buffer.h"
#include "particles/splat_floor.h"

namespace nimbus::media {

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
    std::vector<std::uint32_t> blockRankOf;  // per particle: its block's place in backToFront
    std::vector<std::uint8_t> wideFromLamps;         // per block: the lamps' slices take its particles one by one
    std::vector<std::uint32_t> lampSliceParticles;   // those particles
    std::vector<std::uint8_t> builds;                // per block: the composite variant (kBlockExactCut, ...)
};

namespace {
constexpr int kMaxAtlasSize = 4096;
}

MediaMode parseMediaMode(const std::string& text, const std::string& origin) {
    if (text == "particles") return MediaMode::Particles;
    if (text == "blocks") return MediaMode::Blocks;
    if (text == "billboards") return MediaMode::Billboards;
    if (text == "raymarch") return MediaMode::Raymarch;
    throwInputError(origin, text, "", "unknown media mode (known: particles, blocks, billboards, raymarch)");
}

const char* mediaModeName(MediaMode mode) {
    switch (mode) {
        case MediaMode::Particles: return "particles";
        case MediaMode::Blocks: return "blocks";
        case MediaMode::Billboards: return "billboards";
        case MediaMode::Raymarch: return "raymarch";
    }
    return "unknown";
}

Aabb particleBounds(const ParticleSet& particles) {
    Aabb bounds;
    for (std::size_t i = 0; i < particles.size(); ++i) {
        const glm::dvec3 r(particles.radius[i]);
        bounds.extend(particles.position[i] - r);
        bounds.extend(particles.position[i] + r);
    }
    return bounds;
}

SplatFootprint splatFootprint(const ParticleSet& particles, const gpu::View& view) {
    const double pixels = static_cast<double>(view.width) * view.height;
    const glm::dmat4 viewMatrix(view.view);
    // Pixels per metre at depth 1 (perspective) or per metre (orthographic), vertically.
    const double scale = view.height / (2.0 * (view.orthographic ? view.orthoHalfExtent.y : view.tanHalfFovY));
    double covered = 0.0, radiusTimesArea = 0.0;
    for (std::size_t i = 0; i < particles.size(); ++i) {
        const glm::dvec3 c(viewMatrix * glm::dvec4(particles.position[i] - view.origin, 1.0));
        const double r = particles.radius[i], depth = -c.z;
        if (!view.orthographic && depth <= r) {
            covered += pixels;  // in front of or around the eye: a full-screen quad
            radiusTimesArea += pixels * std::sqrt(pixels);
            continue;
        }
        const double half = r * scale / (view.orthographic ? 1.0 : depth);  // the quad's half size in pixels
        const double area = std::min(4.0 * half * half, pixels);
        covered += area;
        radiusTimesArea += area * half;
    }
    return {covered / pixels, covered > 0.0 ? radiusTimesArea / covered : 0.0};
}

float automaticMediaScale(const SplatFootprint& footprint, bool lampAmongParticles) {
    // A lamp among the particles lights a peak a few pixels wide, which a lower resolution blurs away.
    if (footprint.coverage <= kHalfScaleCoverage || lampAmongParticles) return 1.0f;
    return static_cast<float>(std::clamp(kAutoScaleRadiusTexels / footprint.radiusPixels, 0.25, 0.5));
}

bool lampAmongParticles(const std::vector<Light>& lights, const Aabb& bounds) {
    return std::any_of(lights.begin(), lights.end(), [&](const Light& l) {
        return l.kind != gpu::LightKind::Directional && bounds.contains(l.position);
    });
}

bool lampInsideMedium(const ParticleSet& particles, const std::vector<Light>& lights) {
    // Peak column through a particle's centre: σ ∫ e^{−k u²} du over the chord ≈ 0.8355·σR.
    constexpr double kColumnPerSigmaRadius = 0.8355;
    for (const auto& light : lights) {
        if (light.kind == gpu::LightKind::Directional) continue;
        for (std::size_t i = 0; i < particles.size(); ++i) {
            const double r = particles.radius[i];
            if (kColumnPerSigmaRadius * particles.sigma[i] * r > kLampMediumColumn && glm::length(light.position - particles.position[i]) < r)
                return true;
        }
    }
    return false;
}

bool eyeInsideMedium(const ParticleSet& particles, const gpu::View& view) {
    for (std::size_t i = 0; i < particles.size(); ++i) {
        const glm::dvec3 d = particles.position[i] - view.origin;
        // Orthographic rays start on the camera's plane: a particle crossing it holds their start.
        const double distance = view.orthographic ? std::abs(glm::dot(d, view.forward)) : glm::length(d);
        if (distance < particles.radius[i]) return true;
    }
    return false;
}

MediaRenderer::MediaRenderer() = default;
MediaRenderer::~MediaRenderer() = default;

MediaRenderSettings withDefaults(MediaRenderSettings s) {
    if (s.sliceResolution <= 0) s.sliceResolution = 256;
    if (s.impostorScale <= 0.0f) s.impostorScale = 0.5f;
    if (s.mediaScale <= 0.0f) s.mediaScale = 1.0f;
    if (s.upsampleThreshold <= 0.0f) s.upsampleThreshold = 0.2f;
    return s;
}

void MediaRenderer::prepare(const ParticleSet& particles, const MediaRenderSettings& settings) {
    particles_ = &particles;
    settings_ = withDefaults(settings);
    bounds_ = particleBounds(particles);
    stats_ = {};
    stats_.particles = particles.size();
}

// Blocks mode: this frame's partition and which blocks the lamps' slices take one by one.
void MediaRenderer::partitionBlocks(const GraphFrame& context) {
    if (!blockFrame_) blockFrame_ = std::make_unique<BlockFrame>();
    if (!blockBuffers_) blockBuffers_ = std::make_unique<BlockGpuBuffers>();
    BlockFrame& frame = *blockFrame_;
    const std::vector<glm::dvec3> lamps = lampPositions(context.host.lights);
    frame.partition = partitionIntoBlocks(*particles_, settings_.blocks, lamps);
    frame.instanced = settings_.instancing;
    frame.prototype = choosePrototype(frame.partition);
    frame.lightPlans.clear();
    // An instance has no particles of its own to draw one by one.
    frame.wideFromLamps = frame.instanced ? std::vector<std::uint8_t>(frame.partition.blocks.size(), 0)
                                          : blocksSeenWideFromLamps(frame.partition, lamps);
    frame.lampSliceParticles.clear();
    for (std::size_t b = 0; b < frame.partition.blocks.size(); ++b) {
        if (frame.wideFromLamps[b] == 0) continue;
        const Block& block = frame.partition.blocks[b];
        frame.lampSliceParticles.insert(frame.lampSliceParticles.end(), frame.partition.order.begin() + block.first,
                                        frame.partition.order.begin() + block.first + block.count);
    }
    stats_.blocks = static_cast<int>(frame.partition.blocks.size());
    stats_.lampSliceParticles = frame.lampSliceParticles.size();
}

// The `media_upload` pass: the plugin's uniform blocks, the particles and, by mode, their draw
// order, lamp neighbourhoods or blocks, uploaded before their first draw.
void MediaRenderer::addUploadPass(gpu::FrameGraph& graph, GraphFrame& context) {
    const bool blocks = settings_.mode == MediaMode::Blocks;
    struct Upload {};
    graph.addPass<Upload>(
        "media_upload", [](gpu::PassBuilder& builder, Upload&) { builder.sideEffect(); },
        [this, &context, blocks](const gpu::PassResources&, const Upload&) {
            blocks_->upload();
            buffer_->upload(*particles_, context.host.camera.origin);
            if (!blocks) {
                buffer_->sortBackToFront(*particles_, context.host.camera);
                buffer_->uploadLampNeighbourhoods(*particles_, context.host.lights);
                return;
            }
            // Everything blocks mode draws from this frame, uploaded before its first draw.
            BlockFrame& frame = *blockFrame_;
            if (frame.instanced) blockBuffers_->uploadItems(frame.partition, frame.prototype);
            else blockBuffers_->uploadItems(frame.partition);
            std::vector<const BlockViewPlan*> plans{&frame.cameraPlan};
            for (const BlockViewPlan& plan : frame.lightPlans) plans.push_back(&plan);
            blockBuffers_->uploadTileSets(plans);
            blockBuffers_->uploadDrawOrder(frame.backToFront);
            blockBuffers_->uploadOrderNeighbours(frame.orderNeighbours);
            blockBuffers_->uploadLampSliceParticles(frame.lampSliceParticles);
            if (!anyLamp(context.host.lights)) return;
            frame.blockRankOf.assign(particles_->size(), 0u);
            double largestBlock = 0.0;  // a lamp's 1/d² varies across a block within about its size of the lamp
            for (std::size_t r = 0; r < frame.backToFront.size(); ++r) {
                const Block& block = frame.partition.blocks[frame.backToFront[r]];
                largestBlock = std::max(largestBlock, block.radius);
                for (std::uint32_t k = block.first; k < block.first + block.count; ++k)
                    frame.blockRankOf[frame.partition.order[k]] = static_cast<std::uint32_t>(r);
            }
            buffer_->uploadLampNeighbourhoods(*particles_, context.host.lights, frame.blockRankOf, LampsListed::All, largestBlock);
        });

}

// The media target: its resolution (media_scale, or automatic from the billboards' footprint).
void MediaRenderer::planTarget(const GraphFrame& context) {
    const gpu::View& v = context.host.camera;
    float scale = std::min(settings_.mediaScale, 1.0f);
    const SplatFootprint footprint = splatFootprint(*particles_, v);
    coverage_ = footprint.coverage;
    if (settings_.mediaScaleAuto) scale = automaticMediaScale(footprint, lampAmongParticles(context.host.lights, bounds_));
    stats_.mediaScale = scale;
    if (!target_) target_ = std::make_unique<MediaTarget>();
    MediaTarget& target = *target_;
    target = MediaTarget{};
    target.size = glm::max(glm::ivec2(glm::round(glm::vec2(v.width, v.height) * scale)), glm::ivec2(1));
    target.fullResScale = glm::vec2(v.width, v.height) / glm::vec2(target.size);
    if (target.size != glm::ivec2(v.width, v.height)) target.name = "media_color_low";
}

// Blocks mode, from the camera: the impostor plan, the back-to-front order and how each block is
// composited. Planned with the light slices, so everything blocks mode draws is uploaded before
// its first draw whether the host runs one graph or two.
void MediaRenderer::planBlockCamera(const GraphFrame& context) {
    const gpu::View& v = context.host.camera;
    const MediaTarget& target = *target_;
    const ImpostorView view{v.view, v.viewProjection, !v.orthographic, glm::vec3(0.0f), v.znear, target.size};
    BlockFrame& frame = *blockFrame_;
    frame.cameraPlan = planFor(view, v.origin, {});
    for (std::size_t b = 0; b < frame.cameraPlan.tiles.size(); ++b)
        frame.cameraPlan.tiles[b].lampSlices.x = frame.wideFromLamps[b] != 0 ? 1.0f : 0.0f;
    stats_.impostorAtlas = frame.cameraPlan.atlasSize;
    // Back to front by distance from the eye to the block centre (depth along the axis when orthographic).
    std::vector<double> keys(frame.partition.blocks.size());
    for (std::size_t b = 0; b < keys.size(); ++b) {
        const glm::dvec3 d = frame.partition.blocks[b].centre - v.origin;
        keys[b] = v.orthographic ? glm::dot(d, v.forward) : glm::length(d);
    }
    frame.backToFront.resize(keys.size());
    std::iota(frame.backToFront.begin(), frame.backToFront.end(), 0u);
    std::stable_sort(frame.backToFront.begin(), frame.backToFront.end(),
                     [&](std::uint32_t a, std::uint32_t b) { return keys[a] > keys[b]; });
    const std::vector<OccluderBox>& meshes = context.host.occluders;
    frame.builds = blocksNearMeshes(frame.partition, meshes);
    frame.orderNeighbours.clear();
    if (!frame.instanced) {  // an instance's particles are not listed
        const std::vector<std::uint8_t> own = blocksOfUnresolvedParticles(frame.partition, *particles_, context.sliceViews, v.origin);
        const std::vector<std::uint8_t> exact = settings_.blockShading != BlockShading::Smooth ? blocksShadedExactly(frame.partition, meshes, frame.cameraPlan, v)
                                                                      : std::vector<std::uint8_t>(frame.builds.size(), 0);
        for (std::size_t b = 0; b < frame.builds.size(); ++b)
            frame.builds[b] = static_cast<std::uint8_t>(frame.builds[b] | (own[b] ? kBlockOwnParticles : 0) | (exact[b] ? kBlockExactShading : 0));
        if (std::find(exact.begin(), exact.end(), std::uint8_t{1}) != exact.end())
            frame.orderNeighbours = overlappingBlockLists(frame.partition, frame.backToFront);
        stats_.exactlyShadedBlocks = static_cast<int>(std::count(exact.begin(), exact.end(), std::uint8_t{1}));
    }
}

void MediaRenderer::addLightSlices(gpu::FrameGraph& graph, GraphFrame& context) {
    context.slices = context.color = context.depthUsed = {};
    context.sliceViews.clear();
    context.blocks = nullptr;
    if (particles_ == nullptr || particles_->empty()) return;
    if (!buffer_) buffer_ = std::make_unique<ParticleGpuBuffer>();
    if (!blocks_) blocks_ = std::make_unique<FrameBlocks>();
    context.blocks = blocks_.get();
    const bool blocks = settings_.mode == MediaMode::Blocks;
    planTarget(context);
    if (blocks) partitionBlocks(context);
    addUploadPass(graph, context);
    std::vector<SliceView> views;
    std::vector<glm::ivec2> perLight;
    const int resolution = settings_.mode == MediaMode::Billboards ? 0 : planSliceViews(context, views, perLight);
    for (const SliceView& v : views)
        context.sliceViews.push_back(gpu::packLightView(v.view, v.firstLayer, static_cast<float>(v.slices), static_cast<float>(resolution)));
    blocks_->pack(context.host, context.sliceViews, perLight);
    stats_.sliceResolution = resolution;
    stats_.sliceViews = static_cast<int>(views.size());
    if (blocks) planBlockCamera(context);
    if (views.empty()) return;
    if (blocks) {
        for (const SliceView& v : views) {
            const ImpostorView view{v.view.view, v.view.viewProjection, v.view.perspective, v.lightOrigin, 0.0f,
                                    glm::ivec2(resolution)};
            // A lamp's views leave out the blocks whose particles its slices take one by one.
            const std::vector<std::uint8_t> none;
            blockFrame_->lightPlans.push_back(planFor(view, context.host.camera.origin, view.perspective ? blockFrame_->wideFromLamps : none));
        }
        if (!impostorRenderer_) impostorRenderer_ = std::make_unique<BlockImpostorRenderer>();
        if (!blockSlicePass_) blockSlicePass_ = std::make_unique<BlockSlicePass>();
        const BlockLightImpostors impostors = addBlockLightImpostorPass(graph, blockFrame_->lightPlans, *blockBuffers_, *buffer_, *impostorRenderer_);
        context.slices = blockSlicePass_->add(graph, views, blockFrame_->lightPlans, impostors, resolution, *blockBuffers_);
        const bool lampViews = std::any_of(views.begin(), views.end(), [](const SliceView& v) { return v.view.perspective; });
        if (lampViews && !blockFrame_->lampSliceParticles.empty()) {
            if (!lampSlicePass_) lampSlicePass_ = std::make_unique<BlockLampSlicePass>();
            context.slices = lampSlicePass_->add(graph, context.slices, views, resolution, *blockBuffers_, *buffer_);
        }
        return;
    }
    // Deposit pays per slab a particle reaches; around a lamp inside the medium every particle
    // that reaches the lamp's plane covers a whole cube face in each, and drawing it once wins.
    const bool lampViews = std::any_of(views.begin(), views.end(), [](const SliceView& v) { return v.view.perspective; });
    const bool deposit = settings_.sliceDeposit == SliceDeposit::On || (settings_.sliceDeposit == SliceDeposit::Auto && !lampViews);
    if (deposit && LightSliceDepositPass::supported()) {
        std::vector<std::uint32_t> pieces;
        std::vector<int> firstPiece{0};
        for (const SliceView& v : views) {
            appendSlabPieces(*particles_, v.view, context.host.camera.origin, v.slices, pieces);
            firstPiece.push_back(static_cast<int>(pieces.size()));
        }
        if (!depositPass_) depositPass_ = std::make_unique<LightSliceDepositPass>();
        if (!prefixPass_) prefixPass_ = std::make_unique<LightSlicePrefixPass>();
        const gpu::ResourceHandle slabs = depositPass_->add(graph, views, resolution, *buffer_, std::move(pieces), std::move(firstPiece));
        context.slices = prefixPass_->add(graph, views, resolution, slabs);
        return;
    }
    if (!slicePass_) slicePass_ = std::make_unique<LightSlicePass>();
    context.slices = slicePass_->add(graph, views, resolution, *buffer_);
}

// Every light's slice views around the particles, with their slice counts and layers; returns the
// slices' resolution. `perLight`: (first view, count) per light, count 0 where it has none.
int MediaRenderer::planSliceViews(const GraphFrame& context, std::vector<SliceView>& views, std::vector<glm::ivec2>& perLight) {
    int layers = 0, resolution = settings_.sliceResolution;
    if (settings_.sliceTexelsPerRadius > 0.0f) resolution = 0;  // automatic: the largest any view needs
    const glm::dvec3 origin = context.host.camera.origin;
    perLight.assign(context.host.lights.size(), glm::ivec2(0));
    for (std::size_t i = 0; i < context.host.lights.size(); ++i) {
        const Light& light = context.host.lights[i];
        if (light.range > 0.0 && light.kind != gpu::LightKind::Directional) {
            const glm::dvec3 nearest = glm::clamp(light.position, bounds_.min, bounds_.max);
            if (glm::length(nearest - light.position) >= light.range) continue;  // out of reach
        }
        const auto lightViews = gpu::makeLightViews(light, bounds_, origin);
        perLight[i] = glm::ivec2(static_cast<int>(views.size()), static_cast<int>(lightViews.size()));
        for (auto view : lightViews) {
            const SliceEstimate estimate = estimateSlices(*particles_, view, origin);
            const int slices = settings_.slices > 0 ? std::clamp(settings_.slices, kMinSlices, kMaxSlices) : estimate.slices;
            view.depthNear = static_cast<float>(estimate.depthNear);
            view.depthFar = static_cast<float>(estimate.depthFar);
            if (settings_.sliceTexelsPerRadius > 0.0f)
                resolution = std::max(resolution, sliceResolutionFor(estimate, view, settings_.sliceTexelsPerRadius));
            views.push_back({view, glm::vec3(light.position - origin), slices, layers});
            layers += (slices + 3) / 4;
            stats_.slices = std::max(stats_.slices, slices);
        }
    }
    return resolution;
}

GLuint MediaRenderer::sliceViewsBlock() const { return blocks_ ? blocks_->sliceViews() : 0; }

double MediaRenderer::measureSplatFloor(const gpu::View& view, int repeats) {
    if (!buffer_) return 0.0;
    if (!splatFloor_) splatFloor_ = std::make_unique<SplatFloor>();
    return splatFloor_->measure(*buffer_, view, repeats);
}

BlockViewPlan MediaRenderer::planFor(const ImpostorView& view, const glm::dvec3& origin, const std::vector<std::uint8_t>& notDrawn) const {
    const BlockFrame& frame = *blockFrame_;
    return frame.instanced ? planInstancedBlockView(frame.partition, frame.prototype, view, origin, settings_.impostorScale, kMaxAtlasSize)
                           : planBlockView(frame.partition, view, origin, settings_.impostorScale, kMaxAtlasSize, notDrawn);
}


void MediaRenderer::addMedia(gpu::FrameGraph& graph, GraphFrame& context) {
    context.color = context.depthUsed = {};
    if (particles_ == nullptr || particles_->empty() || context.blocks == nullptr) return;
    const gpu::View& v = context.host.camera;
    const MediaTarget& target = *target_;
    const bool reduced = target.size != glm::ivec2(v.width, v.height);

    gpu::ResourceHandle media;
    if (settings_.mode == MediaMode::Blocks) {
        BlockFrame& frame = *blockFrame_;
        if (!impostorRenderer_) impostorRenderer_ = std::make_unique<BlockImpostorRenderer>();
        if (!blockCompositePass_) blockCompositePass_ = std::make_unique<BlockCompositePass>();
        const BlockImpostorAtlas atlas = addBlockImpostorPass(graph, frame.cameraPlan, *blockBuffers_, *buffer_, *impostorRenderer_);
        media = blockCompositePass_->add(graph, context, atlas, frame.backToFront, frame.builds, settings_.blockShading == BlockShading::Seam,
                                         *blockBuffers_, *buffer_, target);
    } else if (settings_.mode == MediaMode::Billboards) {
        if (!billboardPass_) billboardPass_ = std::make_unique<BillboardPass>();
        media = billboardPass_->add(graph, context, *buffer_, target);
    } else if (settings_.mode == MediaMode::Raymarch) {
        if (!raymarchPass_) raymarchPass_ = std::make_unique<RaymarchPass>();
        const VoxelGrid grid = voxelize(*particles_, settings_.voxels);
        stats_.voxels = grid.size;
        media = raymarchPass_->add(graph, context, grid, settings_.raymarchSteps > 0 ? settings_.raymarchSteps : kDefaultRaymarchSteps, target);
    } else if (settings_.lighting != ParticleLighting::Fragment &&
               !(settings_.exactNearLamps && lampInsideMedium(*particles_, context.host.lights))) {
        if (!lightingPass_) lightingPass_ = std::make_unique<ParticleLightingPass>();
        if (!splatPass_) splatPass_ = std::make_unique<ParticleSplatPass>();
        const FragmentLamps lamps = fragmentLamps(context.host.lights);
        // Billboards of a few pixels: a fit across them has nothing to follow, and at 10⁶ particles
        // its nine rays and varyings cost more than the pixels.
        const bool constant = coverage_ * v.width * v.height < kConstantSplatPixels * static_cast<double>(particles_->size());
        stats_.constantSource = constant;
        lightingPass_->add(graph, context, *buffer_, particles_->size(), settings_.lighting == ParticleLighting::ParticleExact, constant, lamps);
        media = splatPass_->add(graph, context, *buffer_, *lightingPass_, eyeInsideMedium(*particles_, v), constant, lamps, target);
    } else {
        stats_.exactLighting = true;
        if (!particlePass_) particlePass_ = std::make_unique<ParticlePass>();
        media = particlePass_->add(graph, context, *buffer_, {settings_.softParticles, settings_.layerLight}, target);
    }
    context.color = media;
    context.depthUsed = {};
    context.edgeThreshold = 0.2f;
    if (reduced) {
        if (!depthUsedPass_) depthUsedPass_ = std::make_unique<MediaDepthUsedPass>();
        context.depthUsed = depthUsedPass_->add(graph, context, target);
        context.edgeThreshold = settings_.upsampleThreshold;
    }
}

}  // namespace nimbus::media
