#include "nimbus/media/media_renderer.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "block_passes.h"
#include "media_passes.h"
#include "nimbus/base/error.h"
#include "nimbus/media/slice_plan.h"
#include "particle_buffer.h"
#include "splat_floor.h"

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
};

namespace {
constexpr int kMaxAtlasSize = 4096;
}

MediaMode parseMediaMode(const std::string& text, const std::string& origin) {
    if (text == "particles") return MediaMode::Particles;
    if (text == "blocks") return MediaMode::Blocks;
    if (text == "billboards") return MediaMode::Billboards;
    throwInputError(origin, text, "", "unknown media mode (known: particles, blocks, billboards)");
}

const char* mediaModeName(MediaMode mode) {
    switch (mode) {
        case MediaMode::Particles: return "particles";
        case MediaMode::Blocks: return "blocks";
        case MediaMode::Billboards: return "billboards";
    }
    return "unknown";
}

assets::Aabb particleBounds(const ParticleSet& particles) {
    assets::Aabb bounds;
    for (std::size_t i = 0; i < particles.size(); ++i) {
        const glm::dvec3 r(particles.radius[i]);
        bounds.extend(particles.position[i] - r);
        bounds.extend(particles.position[i] + r);
    }
    return bounds;
}

SplatFootprint splatFootprint(const ParticleSet& particles, const render::View& view) {
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

bool lampAmongParticles(const std::vector<assets::ResolvedLight>& lights, const assets::Aabb& bounds) {
    return std::any_of(lights.begin(), lights.end(), [&](const assets::ResolvedLight& l) {
        return l.params.type != assets::LightType::Directional && bounds.contains(l.position);
    });
}

bool lampInsideMedium(const ParticleSet& particles, const std::vector<assets::ResolvedLight>& lights, const glm::dvec3&) {
    // Peak column through a particle's centre: σ ∫ e^{−k u²} du over the chord ≈ 0.8355·σR.
    constexpr double kColumnPerSigmaRadius = 0.8355;
    for (const auto& light : lights) {
        if (light.params.type == assets::LightType::Directional) continue;
        for (std::size_t i = 0; i < particles.size(); ++i) {
            const double r = particles.radius[i];
            if (kColumnPerSigmaRadius * particles.sigma[i] * r > kLampMediumColumn && glm::length(light.position - particles.position[i]) < r)
                return true;
        }
    }
    return false;
}

bool eyeInsideMedium(const ParticleSet& particles, const render::View& view) {
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

void MediaRenderer::prepare(const ParticleSet& particles, const MediaRenderSettings& settings) {
    particles_ = &particles;
    settings_ = settings;
    bounds_ = particleBounds(particles);
    stats_ = {};
    stats_.particles = particles.size();
}

void MediaRenderer::beforeOpaque(render::FrameGraph& graph, render::FrameContext& context) {
    if (particles_ == nullptr || particles_->empty()) return;
    if (!buffer_) buffer_ = std::make_unique<ParticleGpuBuffer>();
    const bool blocks = settings_.mode == MediaMode::Blocks;
    if (blocks) {
        if (!blockFrame_) blockFrame_ = std::make_unique<BlockFrame>();
        if (!blockBuffers_) blockBuffers_ = std::make_unique<BlockGpuBuffers>();
        BlockFrame& frame = *blockFrame_;
        const std::vector<glm::dvec3> lamps = lampPositions(context.input.lights);
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

    struct Upload {};
    graph.addPass<Upload>(
        "media_upload", [](render::PassBuilder& builder, Upload&) { builder.sideEffect(); },
        [this, &context, blocks](const render::PassResources&, const Upload&) {
            buffer_->upload(*particles_, context.view.origin);
            if (!blocks) {
                buffer_->sortBackToFront(*particles_, context.view);
                buffer_->uploadLampNeighbourhoods(*particles_, context.input.lights);
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
            if (!anyLamp(context.input.lights)) return;
            frame.blockRankOf.assign(particles_->size(), 0u);
            double largestBlock = 0.0;  // a lamp's 1/d² varies across a block within about its size of the lamp
            for (std::size_t r = 0; r < frame.backToFront.size(); ++r) {
                const Block& block = frame.partition.blocks[frame.backToFront[r]];
                largestBlock = std::max(largestBlock, block.radius);
                for (std::uint32_t k = block.first; k < block.first + block.count; ++k)
                    frame.blockRankOf[frame.partition.order[k]] = static_cast<std::uint32_t>(r);
            }
            buffer_->uploadLampNeighbourhoods(*particles_, context.input.lights, frame.blockRankOf, LampsListed::All, largestBlock);
        });

    if (settings_.mode == MediaMode::Billboards) return;  // sprites without volumetric shadows: no slices
    std::vector<SliceView> views;
    int layers = 0, resolution = settings_.sliceResolution > 0 ? settings_.sliceResolution : 256;
    if (settings_.sliceTexelsPerRadius > 0.0f) resolution = 0;  // automatic: the largest any view needs
    context.transmittance.perLight.assign(context.input.lights.size(), glm::ivec2(0));
    for (std::size_t i = 0; i < context.input.lights.size(); ++i) {
        const auto& light = context.input.lights[i];
        if (light.params.range > 0.0 && light.params.type != assets::LightType::Directional) {
            const glm::dvec3 nearest = glm::clamp(light.position, bounds_.min, bounds_.max);
            if (glm::length(nearest - light.position) >= light.params.range) continue;  // out of reach
        }
        const auto lightViews = render::makeLightViews(light, bounds_, context.view.origin);
        context.transmittance.perLight[i] = glm::ivec2(static_cast<int>(views.size()), static_cast<int>(lightViews.size()));
        for (auto view : lightViews) {
            const SliceEstimate estimate = estimateSlices(*particles_, view, context.view.origin);
            const int slices = settings_.slices > 0 ? std::clamp(settings_.slices, kMinSlices, kMaxSlices) : estimate.slices;
            view.depthNear = static_cast<float>(estimate.depthNear);
            view.depthFar = static_cast<float>(estimate.depthFar);
            if (settings_.sliceTexelsPerRadius > 0.0f)
                resolution = std::max(resolution, sliceResolutionFor(estimate, view, settings_.sliceTexelsPerRadius));
            views.push_back({view, glm::vec3(light.position - context.view.origin), slices, layers});
            layers += (slices + 3) / 4;
            stats_.slices = std::max(stats_.slices, slices);
        }
    }
    for (const SliceView& v : views)
        context.transmittance.views.push_back(render::packLightView(v.view, v.firstLayer, static_cast<float>(v.slices), static_cast<float>(resolution)));
    stats_.sliceResolution = resolution;
    stats_.sliceViews = static_cast<int>(views.size());
    if (views.empty()) return;
    if (blocks) {
        for (const SliceView& v : views) {
            const ImpostorView view{v.view.view, v.view.viewProjection, v.view.perspective, v.lightOrigin, 0.0f,
                                    glm::ivec2(resolution)};
            // A lamp's views leave out the blocks whose particles its slices take one by one.
            const std::vector<std::uint8_t> none;
            blockFrame_->lightPlans.push_back(planFor(view, context.view.origin, view.perspective ? blockFrame_->wideFromLamps : none));
        }
        if (!impostorRenderer_) impostorRenderer_ = std::make_unique<BlockImpostorRenderer>();
        if (!blockSlicePass_) blockSlicePass_ = std::make_unique<BlockSlicePass>();
        context.transmittanceSlices = blockSlicePass_->add(graph, views, blockFrame_->lightPlans, resolution, *blockBuffers_,
                                                           *buffer_, *impostorRenderer_);
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
            appendSlabPieces(*particles_, v.view, context.view.origin, v.slices, pieces);
            firstPiece.push_back(static_cast<int>(pieces.size()));
        }
        if (!depositPass_) depositPass_ = std::make_unique<LightSliceDepositPass>();
        if (!prefixPass_) prefixPass_ = std::make_unique<LightSlicePrefixPass>();
        const render::ResourceHandle slabs = depositPass_->add(graph, views, resolution, *buffer_, std::move(pieces), std::move(firstPiece));
        context.transmittanceSlices = prefixPass_->add(graph, views, resolution, slabs);
        return;
    }
    if (!slicePass_) slicePass_ = std::make_unique<LightSlicePass>();
    context.transmittanceSlices = slicePass_->add(graph, views, resolution, *buffer_);
}

double MediaRenderer::measureSplatFloor(const render::View& view, int repeats) {
    if (!buffer_) return 0.0;
    if (!splatFloor_) splatFloor_ = std::make_unique<SplatFloor>();
    return splatFloor_->measure(*buffer_, view, repeats);
}

BlockViewPlan MediaRenderer::planFor(const ImpostorView& view, const glm::dvec3& origin, const std::vector<std::uint8_t>& notDrawn) const {
    const BlockFrame& frame = *blockFrame_;
    return frame.instanced ? planInstancedBlockView(frame.partition, frame.prototype, view, origin, impostorScale(), kMaxAtlasSize)
                           : planBlockView(frame.partition, view, origin, impostorScale(), kMaxAtlasSize, notDrawn);
}

float MediaRenderer::impostorScale() const { return settings_.impostorScale > 0.0f ? settings_.impostorScale : 0.5f; }

void MediaRenderer::afterOpaque(render::FrameGraph& graph, render::FrameContext& context) {
    if (particles_ == nullptr || particles_->empty()) return;
    const render::View& v = context.view;
    float scale = settings_.mediaScale > 0.0f ? std::min(settings_.mediaScale, 1.0f) : 1.0f;
    const SplatFootprint footprint = splatFootprint(*particles_, v);
    const double coverage = footprint.coverage;
    if (settings_.mediaScaleAuto) scale = automaticMediaScale(footprint, lampAmongParticles(context.input.lights, bounds_));
    stats_.mediaScale = scale;
    MediaTarget target;
    target.size = glm::max(glm::ivec2(glm::round(glm::vec2(v.width, v.height) * scale)), glm::ivec2(1));
    target.fullResScale = glm::vec2(v.width, v.height) / glm::vec2(target.size);
    const bool reduced = target.size != glm::ivec2(v.width, v.height);
    if (reduced) target.name = "media_color_low";

    render::ResourceHandle media;
    if (settings_.mode == MediaMode::Blocks) {
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
        if (!impostorRenderer_) impostorRenderer_ = std::make_unique<BlockImpostorRenderer>();
        if (!blockCompositePass_) blockCompositePass_ = std::make_unique<BlockCompositePass>();
        const std::vector<MeshBox> meshes = meshInstanceBoxes(context.input);
        std::vector<std::uint8_t> builds = blocksNearMeshes(frame.partition, meshes);
        frame.orderNeighbours.clear();
        if (!frame.instanced) {  // an instance's particles are not listed
            const std::vector<std::uint8_t> own = blocksOfUnresolvedParticles(frame.partition, *particles_, context.transmittance.views, v.origin);
            const std::vector<std::uint8_t> exact = settings_.blockShading != BlockShading::Smooth ? blocksShadedExactly(frame.partition, meshes, frame.cameraPlan, v)
                                                                          : std::vector<std::uint8_t>(builds.size(), 0);
            for (std::size_t b = 0; b < builds.size(); ++b)
                builds[b] = static_cast<std::uint8_t>(builds[b] | (own[b] ? kBlockOwnParticles : 0) | (exact[b] ? kBlockExactShading : 0));
            if (std::find(exact.begin(), exact.end(), std::uint8_t{1}) != exact.end())
                frame.orderNeighbours = overlappingBlockLists(frame.partition, frame.backToFront);
            stats_.exactlyShadedBlocks = static_cast<int>(std::count(exact.begin(), exact.end(), std::uint8_t{1}));
        }
        const BlockImpostorAtlas atlas = addBlockImpostorPass(graph, frame.cameraPlan, *blockBuffers_, *buffer_, *impostorRenderer_);
        media = blockCompositePass_->add(graph, context, atlas, frame.backToFront, builds, settings_.blockShading == BlockShading::Seam,
                                         *blockBuffers_, *buffer_, target);
    } else if (settings_.mode == MediaMode::Billboards) {
        if (!billboardPass_) billboardPass_ = std::make_unique<BillboardPass>();
        media = billboardPass_->add(graph, context, *buffer_, target);
    } else if (settings_.lighting != ParticleLighting::Fragment &&
               !(settings_.exactNearLamps && lampInsideMedium(*particles_, context.input.lights, v.origin))) {
        if (!lightingPass_) lightingPass_ = std::make_unique<ParticleLightingPass>();
        if (!splatPass_) splatPass_ = std::make_unique<ParticleSplatPass>();
        const FragmentLamps lamps = fragmentLamps(context.input.lights);
        // Billboards of a few pixels: a fit across them has nothing to follow, and at 10⁶ particles
        // its nine rays and varyings cost more than the pixels.
        const bool constant = coverage * v.width * v.height < kConstantSplatPixels * static_cast<double>(particles_->size());
        stats_.constantSource = constant;
        lightingPass_->add(graph, context, *buffer_, particles_->size(), settings_.lighting == ParticleLighting::ParticleExact, constant, lamps);
        media = splatPass_->add(graph, context, *buffer_, *lightingPass_, eyeInsideMedium(*particles_, v), constant, lamps, target);
    } else {
        stats_.exactLighting = true;
        if (!particlePass_) particlePass_ = std::make_unique<ParticlePass>();
        media = particlePass_->add(graph, context, *buffer_, {settings_.softParticles, settings_.layerLight}, target);
    }
    context.overlay = {media, {}, 0.2f};
    if (reduced) {
        if (!depthUsedPass_) depthUsedPass_ = std::make_unique<MediaDepthUsedPass>();
        context.overlay.depthUsed = depthUsedPass_->add(graph, context, target);
        if (settings_.upsampleThreshold > 0.0f) context.overlay.edgeThreshold = settings_.upsampleThreshold;
    }
}

}  // namespace nimbus::media
