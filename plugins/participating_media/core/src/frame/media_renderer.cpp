#include "nimbus/media/media_renderer.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "common/frame_blocks.h"
#include "common/particle_buffer.h"
#include "common/shared_frame.h"
#include "frame/immediate_frame.h"
#include "nimbus/base/error.h"
#include "nimbus/media/gpu_bindings.h"
#include "nimbus/media/slice_plan.h"
#include "particles/splat_floor.h"
#include "planning/slice_crop.h"
#include "slices/light_slice_intervals_pass.h"
#include "upsample/media_depth_used_pass.h"
#include "upsample/media_edge_stencil_pass.h"
#include "upsample/media_seam_marks_pass.h"

namespace nimbus::media {

namespace {
constexpr float kNegligibleRescatter = 0.01f;  // planScattering
// A point or spot light's own views may take fewer texels than the array holds: inside the medium
// its particles subtend tens of degrees, and campfire's lamp faces wanted 12 texels where the sun
// wanted 48 (docs/design-notes.md).
constexpr int kMinLampSliceResolution = 16;

// The lamps' views' texels per side (they all take one: planSliceViews), 0 where they are whole.
int lampSliceTexels(const SharedFrame& shared) {
    for (const SliceView& v : shared.sliceViews)
        if (v.view.perspective) return v.resolution;
    return 0;
}
}  // namespace

double MediaFrameStats::value(const std::string& key, double fallback) const {
    for (const TechniqueStat& s : technique)
        if (s.key == key) return std::visit([](auto v) { return static_cast<double>(v); }, s.value);
    return fallback;
}

MediaRenderer::MediaRenderer(TechniqueTable techniques)
    : techniques_(std::move(techniques)), shared_(std::make_unique<SharedFrame>()) {}
MediaRenderer::~MediaRenderer() = default;

Aabb MediaRenderer::bounds() const { return shared_->bounds; }

// The multiple-scattering model's environment is dark where a mesh lies.
bool MediaRenderer::readsOccluders() const {
    return technique_ != nullptr && (technique_->readsOccluders() || techniques_.at(settings_.mode).multipleScattering);
}

void MediaRenderer::forgetFrames() {
    for (auto& [name, technique] : made_) technique->forgetFrames();
    // An answer solved from an earlier frame's (scattering_warm_sweeps) is not this frame's alone; a
    // cold one is, and an unchanged medium keeps it.
    if (shared_->environment.warm) shared_->environment = {};
}

// A mode that does not draw volumes refuses a frame with one rather than leave it out of the picture.
void MediaRenderer::refuseVolumes(const TechniqueEntry& entry, const Volume& volume) const {
    std::string drawing;
    for (const TechniqueEntry& e : techniques_.entries())
        if (e.volumes) drawing += (drawing.empty() ? "" : ", ") + e.name;
    throwInputError(volume.origin.empty() ? "a volume" : volume.origin, "", "extensions.NIMBUS_participating_media.volume",
                    "media mode " + entry.name + " does not draw volumes (modes that do: " + (drawing.empty() ? "none" : drawing) + ")");
}

MediaTechnique& MediaRenderer::technique(const TechniqueEntry& entry) {
    std::unique_ptr<MediaTechnique>& made = made_[entry.name];
    if (!made) made = entry.create();
    return *made;
}

void MediaRenderer::prepare(const ParticleSet& particles, const MediaRenderSettings& settings, const std::vector<Volume>* volumes) {
    const TechniqueEntry& entry = techniques_.at(settings.mode, "media mode");
    if (volumes != nullptr && !volumes->empty() && !entry.volumes) refuseVolumes(entry, volumes->front());
    particles_ = &particles;
    volumes_ = volumes != nullptr ? volumes : &noVolumes_;
    settings_ = withDefaults(settings);
    settings_.mode = entry.name;
    technique_ = &technique(entry);
    drawsOver_ = entry.drawsOver;
    shared_->bounds = particleBounds(particles);
    shared_->bounds.extend(volumeBounds(*volumes_));
    stats_ = {};
    stats_.particles = particles.size();
    stats_.mode = entry.name;
    frame_ = {&particles, volumes_, &settings_, shared_.get(), &stats_.technique};
}

// The `media_upload` pass: the plugin's uniform blocks, the particles and what the technique
// draws from this frame, uploaded before their first draw.
void MediaRenderer::addUploadPass(gpu::FrameGraph& graph, GraphFrame& context) {
    struct Upload {};
    graph.addPass<Upload>(
        "media_upload", [](gpu::PassBuilder& builder, Upload&) { builder.sideEffect(); },
        [this, &context](const gpu::PassResources&, const Upload&) {
            shared_->blocks->upload();
            shared_->buffer->upload(*particles_, context.host.camera.origin);
            if (!volumes_->empty()) shared_->volumes->upload(*volumes_, context.host.camera.origin);
            const EnvironmentGrid& grid = shared_->environment;
            if (!grid.empty()) {
                glTextureSubImage3D(shared_->environmentTexture.id(), 0, 0, 0, 0, grid.size.x, grid.size.y, grid.size.z, GL_RGBA, GL_FLOAT,
                                    grid.texels.data());
                glTextureSubImage3D(shared_->directionalTexture.id(), 0, 0, 0, 0, grid.size.x, grid.size.y, grid.size.z, GL_RGBA, GL_FLOAT,
                                    grid.directional.data());
            }
            technique_->upload(frame_, context);
        });
}

// media_scale=auto's footprint: a point light's own particles (within kLampReach of it), lit
// unevenly within each, keep kLampLitRadiusTexels across their typical half size, where it asks
// more than the billboards' kAutoScaleRadiusTexels across all of them.
SplatFootprint MediaRenderer::lampLitFootprint(SplatFootprint all, const std::vector<Light>& lights, const gpu::View& v) const {
    std::vector<int> points;
    for (std::size_t i = 0; i < lights.size(); ++i)
        if (lights[i].kind == gpu::LightKind::Point) points.push_back(static_cast<int>(i));
    if (points.empty()) return all;
    const std::vector<std::uint8_t> near = particlesNearLamps(*particles_, lights, points, kLampReach);
    const SplatFootprint lit = splatFootprint(*particles_, v, &near);
    if (lit.coverage > 0.0) all.radiusPixels = std::min(all.radiusPixels, lit.radiusPixels * kAutoScaleRadiusTexels / kLampLitRadiusTexels);
    return all;
}

// media_scale=auto this frame: `medium` is the layer's rect (0: the viewport), over which compose pays.
float MediaRenderer::automaticScale(const GraphFrame& context, const SplatFootprint& footprint, glm::ivec4 medium, bool peaksRedrawn) const {
    const gpu::View& v = context.host.camera;
    const std::vector<Light>& lights = context.host.lights;
    const double composed = medium.z > 0 ? static_cast<double>(medium.z) * medium.w / (static_cast<double>(v.width) * v.height) : 1.0;
    const bool lampBlurred = lampAmongParticles(lights, shared_->bounds, gpu::LightKind::Spot) ||
                             (!peaksRedrawn && lampAmongParticles(lights, shared_->bounds, gpu::LightKind::Point));
    return automaticMediaScale(lampLitFootprint(footprint, lights, v), composed, lampBlurred);
}

// The media target: its resolution (media_scale, or automatic from the billboards' footprint), the
// rect the layer covers and the lamps' peaks to draw again at full resolution.
void MediaRenderer::planTarget(const GraphFrame& context) {
    const gpu::View& v = context.host.camera;
    const SplatFootprint footprint = splatFootprint(*particles_, v);
    shared_->coverage = footprint.coverage;
    const TechniqueEntry& entry = techniques_.at(settings_.mode);
    // Where the layer may hold anything: the whole viewport (0) unless the mode draws within the medium.
    const glm::ivec4 medium = entry.withinMedium ? mediumRect(*particles_, *volumes_, v, 0) : glm::ivec4(0);
    // A point light's peak is drawn again at full resolution where the mode draws edges.
    const std::vector<glm::dvec2> lamps = entry.edges && entry.lampPeaks && !settings_.upsampleOnly
                                              ? lampImages(*particles_, context.host.lights, v)
                                              : std::vector<glm::dvec2>{};
    const bool peaksRedrawn = entry.edges && entry.lampPeaks && !settings_.upsampleOnly && lampPeaksCompact(lamps, v);
    const float scale = settings_.mediaScaleAuto ? automaticScale(context, footprint, medium, peaksRedrawn) : std::min(settings_.mediaScale, 1.0f);
    stats_.mediaScale = scale;
    shared_->radiusTexels = footprint.radiusPixels * scale;
    MediaTarget& target = shared_->target;
    target = MediaTarget{};
    target.size = glm::max(glm::ivec2(glm::round(glm::vec2(v.width, v.height) * scale)), glm::ivec2(1));
    target.fullResScale = glm::vec2(v.width, v.height) / glm::vec2(target.size);
    const bool reduced = target.size != glm::ivec2(v.width, v.height);
    if (reduced) target.name = "media_color_low";
    const int reach = upsampleReach(target);
    target.cover = growRect(medium, reach, v);
    if (reduced && peaksRedrawn) target.peak = lampPeaks(lamps, v, reach).rect;
}

void MediaRenderer::addLightSlices(gpu::FrameGraph& graph, GraphFrame& context) {
    context.slices = context.color = context.depthUsed = context.edges = {};
    context.sliceViews.clear();
    context.blocks = nullptr;
    context.multiple = false;
    stats_.technique.clear();
    if (particles_ == nullptr || !hasMedium(*particles_, volumes_)) return;
    SharedFrame& shared = *shared_;
    if (!shared.buffer) shared.buffer = std::make_unique<ParticleGpuBuffer>();
    if (!shared.blocks) shared.blocks = std::make_unique<FrameBlocks>();
    if (!volumes_->empty() && !shared.volumes) shared.volumes = std::make_unique<VolumeGpuBuffer>();
    shared.volumeCount = volumes_->size();
    context.blocks = shared.blocks.get();
    planTarget(context);
    technique_->plan(frame_, context);
    addUploadPass(graph, context);
    std::vector<glm::ivec2> perLight;
    shared.sliceViews.clear();
    shared.sliceResolution = 0;
    if (techniques_.at(settings_.mode).lightSlices) planSliceViews(context, perLight);
    for (const SliceView& v : shared.sliceViews)
        context.sliceViews.push_back(
            gpu::packLightView(v.view, intervalLayer(v), static_cast<float>(v.slices), static_cast<float>(sliceTexels(v, shared.sliceResolution))));
    shared.blocks->pack(context.host, context.sliceViews, perLight, {.arrayTexels = shared.sliceResolution, .lampTexels = lampSliceTexels(shared)});
    planScattering(context);
    stats_.sliceResolution = shared.sliceResolution;
    stats_.sliceViews = static_cast<int>(shared.sliceViews.size());
    technique_->addLightSlices(graph, context, frame_);
    // Whichever passes drew them, the slices are read by interval, each with its ends' neighbours
    // (light_slice_intervals_pass.h).
    if (context.slices.valid()) {
        if (!sliceIntervalsPass_) sliceIntervalsPass_ = std::make_unique<LightSliceIntervalsPass>();
        context.slices = sliceIntervalsPass_->add(graph, shared.sliceViews, shared.sliceResolution, context.slices);
    }
}

// Every light's slice views around the particles, with their slice counts and layers, and the
// slices' resolution. `perLight`: (first view, count) per light, count 0 where it has none.
void MediaRenderer::planSliceViews(const GraphFrame& context, std::vector<glm::ivec2>& perLight) {
    SharedFrame& shared = *shared_;
    const bool nearMeshes = meshReachesInto(context.host.occluders, shared.bounds);
    const int fixedSlices = nearMeshes && settings_.slicesNearMeshes > 0 ? settings_.slicesNearMeshes : settings_.slices;
    const float detail = nearMeshes && settings_.sliceTexelsPerRadius > 0.0f && settings_.sliceTexelsPerRadiusNearMeshes > 0.0f
                             ? settings_.sliceTexelsPerRadiusNearMeshes
                             : settings_.sliceTexelsPerRadius;
    // With slice_crop, where a mesh reaches into the medium and the resolution is automatic, a
    // directional light takes a second, finer view over the meshes' overlap (planning/slice_crop.h).
    const bool cropped = nearMeshes && detail > 0.0f && settings_.sliceCrop && techniques_.at(settings_.mode).sliceCrops;
    const double maxRadius = cropped && !particles_->radius.empty() ? *std::max_element(particles_->radius.begin(), particles_->radius.end()) : 0.0;
    stats_.slicesCropped = 0;
    int layers = 0, resolution = settings_.sliceResolution;
    if (detail > 0.0f) resolution = 0;  // automatic: the largest any view needs
    const glm::dvec3 origin = context.host.camera.origin;
    perLight.assign(context.host.lights.size(), glm::ivec2(0));
    for (std::size_t i = 0; i < context.host.lights.size(); ++i) {
        const Light& light = context.host.lights[i];
        if (light.range > 0.0 && light.kind != gpu::LightKind::Directional) {
            const glm::dvec3 nearest = glm::clamp(light.position, shared.bounds.min, shared.bounds.max);
            if (glm::length(nearest - light.position) >= light.range) continue;  // out of reach
        }
        const auto lightViews = gpu::makeLightViews(light, shared.bounds, origin);
        const int first = static_cast<int>(shared.sliceViews.size());
        const auto add = [&](const gpu::LightView& view, int slices, int own) {
            shared.sliceViews.push_back({view, glm::vec3(light.position - origin), slices, layers, own});
            layers += (slices + 3) / 4;
            stats_.slices = std::max(stats_.slices, slices);
        };
        for (auto view : lightViews) {
            const SliceEstimate estimate = estimateSlices(*particles_, *volumes_, view, origin);
            const int slices = fixedSlices > 0 ? std::clamp(fixedSlices, kMinSlices, kMaxSlices) : estimate.slices;
            view.depthNear = static_cast<float>(estimate.depthNear);
            view.depthFar = static_cast<float>(estimate.depthFar);
            int own = 0;  // the array's
            if (detail > 0.0f) {
                // A lamp's views keep the base detail near meshes: its light there is per fragment,
                // with its own mesh shadows, and six finer faces cost the slices most.
                const float viewDetail = view.perspective ? settings_.sliceTexelsPerRadius : detail;
                resolution = std::max(resolution, sliceResolutionFor(estimate, view, viewDetail));
                if (view.perspective) own = sliceResolutionFor(estimate, view, viewDetail, kMinLampSliceResolution);
            }
            add(view, slices, own);
            // The crop follows its whole view, the light's second (light_transmittance.glsl).
            if (cropped && lightViews.size() == 1)
                if (const auto crop = meshCropView(view, slices, context.host.occluders, shared.bounds, maxRadius, origin)) {
                    add(crop->view, crop->slices, 0);
                    shared.sliceViews.back().seedView = static_cast<int>(shared.sliceViews.size()) - 2;
                    ++stats_.slicesCropped;
                }
        }
        perLight[i] = glm::ivec2(first, static_cast<int>(shared.sliceViews.size()) - first);
    }
    shared.sliceResolution = resolution;
    // The lookups read one share of the array's side for every lamp's view (light_transmittance.glsl
    // mediaSliceCount): they all take the largest any asks for.
    int lampTexels = 0;
    for (const SliceView& v : shared.sliceViews)
        if (v.view.perspective) lampTexels = std::max(lampTexels, v.resolution > 0 ? v.resolution : resolution);
    for (SliceView& v : shared.sliceViews)
        if (v.view.perspective) v.resolution = lampTexels < resolution ? lampTexels : 0;
}

// The multiple model's environment grid, packed with the approximation's constants; a single frame
// packs none, and its programs read none. Nor does a multiple frame whose medium rescatters almost
// nothing: where under 1% of the first scattering's light scatters again (ω·(1 − T̄) per voxel, T̄
// its mean transmittance to the outside, weighted by that light), orders ≥ 2 add about that share
// and the environment is about as little attenuated, so the single programs draw it.
void MediaRenderer::planScattering(GraphFrame& context) {
    SharedFrame& shared = *shared_;
    const bool multiple = context.host.scattering == ScatteringModel::Multiple && techniques_.at(settings_.mode).multipleScattering;
    context.multiple = multiple;
    if (!multiple) {
        shared.environment = {};
        shared.blocks->packScattering({}, 0, 0);
        return;
    }
    const auto start = std::chrono::steady_clock::now();
    solveEnvironmentGrid(*particles_, *volumes_, {.lights = &context.host.lights, .ambient = context.host.ambient, .meshes = &context.host.occluders},
                         settings_.scatteringVoxels, {.maxSweeps = settings_.scatteringSweeps, .warmSweeps = settings_.scatteringWarmSweeps},
                         shared.environment);
    const EnvironmentGrid& grid = shared.environment;
    if (grid.sweeps > 0) stats_.scatteringSolveMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    stats_.scatteringWarm = grid.sweeps > 0 && grid.warm;
    for (gpu::Texture* texture : {&shared.environmentTexture, &shared.directionalTexture}) {
        if (*texture && texture->desc().width == grid.size.x && texture->desc().height == grid.size.y && texture->desc().depth == grid.size.z)
            continue;
        *texture = gpu::Texture({.target = GL_TEXTURE_3D, .format = GL_RGBA32F, .width = grid.size.x, .height = grid.size.y, .depth = grid.size.z});
        for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R}) glTextureParameteri(texture->id(), wrap, GL_CLAMP_TO_EDGE);
    }
    // The textures above are sized for the grid either way: the upload pass fills them.
    stats_.rescatter = grid.rescatter;
    if (grid.rescatter < kNegligibleRescatter) {  // thin or dark: the single model's programs, within that much
        context.multiple = false;
        shared.blocks->packScattering({}, 0, 0);
        return;
    }
    stats_.multipleScattering = true;
    const glm::dvec3 extent = glm::dvec3(grid.size) * grid.voxel;
    GpuScattering block;
    block.gridMin = glm::vec4(glm::vec3(grid.min - context.host.camera.origin), 1.0f);
    block.gridInvExtent = glm::vec4(glm::vec3(1.0 / extent), 0.0f);
    shared.blocks->packScattering(block, shared.environmentTexture.id(), shared.directionalTexture.id());
}

GLuint MediaRenderer::sliceViewsBlock() const { return shared_->blocks ? shared_->blocks->sliceViews() : 0; }

double MediaRenderer::measureSplatFloor(const gpu::View& view, int repeats) {
    if (!shared_->buffer) return 0.0;
    if (!splatFloor_) splatFloor_ = std::make_unique<SplatFloor>();
    return splatFloor_->measure(*shared_->buffer, view, repeats);
}

void MediaRenderer::addMedia(gpu::FrameGraph& graph, GraphFrame& context) {
    context.color = context.depthUsed = context.edges = {};
    context.edgeRect = context.coverRect = glm::ivec4(0);
    if (particles_ == nullptr || !hasMedium(*particles_, volumes_) || context.blocks == nullptr) return;
    const gpu::View& v = context.host.camera;
    MediaTarget& target = shared_->target;
    const bool full = target.size == glm::ivec2(v.width, v.height);
    target.over = full && drawsOver_ ? context.output : gpu::ResourceHandle{};
    context.color = technique_->addMedia(graph, context, frame_);
    if (target.over.valid() && context.color == target.over) context.color = {};  // drawn over the output: no layer
    context.coverRect = target.cover;
    context.edgeThreshold = 0.2f;
    if (target.size != glm::ivec2(v.width, v.height)) {
        if (!depthUsedPass_) depthUsedPass_ = std::make_unique<MediaDepthUsedPass>();
        context.depthUsed = depthUsedPass_->add(graph, context, target);
        context.edgeThreshold = settings_.upsampleThreshold;
        const glm::ivec4 meshes = technique_->edgeRect(), rect = unionRects(meshes, target.peak);
        frame_.report("lamp_peak_pixels", static_cast<long long>(target.peak.z) * target.peak.w);
        if (rect.z > 0) {
            // Where a mesh lies inside the medium, its texels become edges too (media_seam_marks_pass.h).
            if (meshes.z > 0 && !settings_.noMeshCuts) {
                if (!seamMarksPass_) seamMarksPass_ = std::make_unique<MediaSeamMarksPass>();
                context.depthUsed = seamMarksPass_->add(graph, context, *shared_->buffer,
                                                        particlesCutByMeshes(context.host.occluders, *particles_), context.depthUsed, target);
            }
            if (!edgeStencilPass_) edgeStencilPass_ = std::make_unique<MediaEdgeStencilPass>();
            const EdgeTarget edges = edgeStencilPass_->add(graph, context, context.depthUsed, target, context.edgeThreshold, rect, target.peak);
            context.edges = technique_->addEdges(graph, context, frame_, edges);
            context.edgeRect = rect;
        }
    }
}

}  // namespace nimbus::media
