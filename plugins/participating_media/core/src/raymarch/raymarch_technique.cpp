#include "raymarch/raymarch_technique.h"

#include <algorithm>

#include "common/shared_frame.h"
#include "nimbus/base/settings.h"
#include "nimbus/media/medium_footprint.h"
#include "raymarch/raymarch_edges_pass.h"
#include "raymarch/raymarch_noise_pass.h"
#include "raymarch/raymarch_pass.h"
#include "raymarch/voxel_grid.h"
#include "slices/particle_slices.h"

namespace nimbus::media {
namespace {

const SettingField<RaymarchSettings> kRaymarchFields[] = {
    {{.key = "voxels",
      .help = "voxels along the grid's longest side",
      .type = SettingType::Integer,
      .min = 4,
      .max = 256,
      .defaultValue = "a voxel per third of the small particles' radius, at most 96"},
     &setInteger<&RaymarchSettings::voxels>},
    {{.key = "raymarch_steps", .help = "most samples per ray", .type = SettingType::Integer, .min = 4, .max = 4096, .defaultValue = "128"},
     &setInteger<&RaymarchSettings::raymarchSteps>},
};

class RaymarchTechnique final : public MediaTechnique {
public:
    // The grid is this frame's medium, voxelised before the light slices (which read its noise).
    void plan(TechniqueFrame& frame, const GraphFrame&) override {
        const RaymarchSettings own = techniqueSettings<RaymarchSettings>(*frame.settings);
        grid_ = voxelize(*frame.particles, *frame.volumes, own.voxels);
        frame.report("voxels_x", static_cast<long long>(grid_.size.x));
        frame.report("voxels_y", static_cast<long long>(grid_.size.y));
        frame.report("voxels_z", static_cast<long long>(grid_.size.z));
    }

    void upload(TechniqueFrame&, const GraphFrame&) override { textures_.upload(grid_); }

    void addLightSlices(gpu::FrameGraph& graph, GraphFrame& context, TechniqueFrame& frame) override {
        const std::vector<Volume>& volumes = *frame.volumes;
        const bool noise = std::any_of(volumes.begin(), volumes.end(), [](const Volume& v) { return v.noise.has_value(); });
        NoiseGridInput grid;
        if (noise) {
            if (!noisePass_) noisePass_ = std::make_unique<RaymarchNoisePass>();
            noisePass_->add(graph, textures_, grid_, volumes, *frame.shared->volumes, context.host.camera.origin);
            grid = {&textures_.noise(), glm::vec3(grid_.min - context.host.camera.origin), glm::vec3(glm::dvec3(grid_.size) * grid_.voxel),
                    static_cast<float>(grid_.voxel.x)};
        }
        slices_.add(graph, context, *frame.particles, *frame.shared, frame.settings->sliceDeposit, noise ? &grid : nullptr);
    }

    gpu::ResourceHandle addMedia(gpu::FrameGraph& graph, GraphFrame& context, TechniqueFrame& frame) override {
        const RaymarchSettings own = techniqueSettings<RaymarchSettings>(*frame.settings);
        if (!pass_) pass_ = std::make_unique<RaymarchPass>();
        const int steps = own.raymarchSteps > 0 ? own.raymarchSteps : kDefaultRaymarchSteps;
        edgeRect_ = frame.settings->upsampleOnly ? glm::ivec4(0)
                                                 : meshEdgeRect(context.host.occluders, *frame.particles, context.host.camera, frame.shared->target.size);
        // The grid's padding voxel reaches past the particles' spheres: the layer covers its box.
        MediaTarget& target = frame.shared->target;
        const OccluderBox box = occluderBox(glm::dmat4(1.0), grid_.min, grid_.min + grid_.voxel * glm::dvec3(grid_.size));
        if (!grid_.empty()) target.cover = unionRects(target.cover, boxRect(box, context.host.camera, upsampleReach(target)));
        march_ = pass_->march(context, grid_, textures_, steps);
        return pass_->add(graph, context, march_, frame.shared->target);
    }

    // Mixed resolution where a mesh enters the particles (a volume's box draws no edges again).
    glm::ivec4 edgeRect() const override { return edgeRect_; }
    gpu::ResourceHandle addEdges(gpu::FrameGraph& graph, GraphFrame& context, TechniqueFrame&, const EdgeTarget& edges) override {
        return addRaymarchEdges(graph, context, march_, edges);
    }

private:
    VoxelGrid grid_;
    RaymarchGrid textures_;
    ParticleSlices slices_;
    std::unique_ptr<RaymarchNoisePass> noisePass_;
    std::unique_ptr<RaymarchPass> pass_;
    glm::ivec4 edgeRect_{0};      // this frame's, as addMedia planned it
    RaymarchPass::March march_;   // this frame's march, for the edges
};

}  // namespace

TechniqueEntry raymarchTechnique() {
    return {.name = "raymarch",
            .help = "the particles and volumes voxelised each frame (noise volumes on the GPU) and the grid ray-marched per pixel, lit through the light slices",
            .sliceDeposit = true,
            .volumes = true,
            .edges = true,
            .lampPeaks = true,  // campfire fast at ¼: 15.2% (14.7% at full resolution, its voxels')
            .withinMedium = true,  // within its padded grid's box, which it widens the cover to
            .settings = specsOf(kRaymarchFields),
            .read = readerOf(kRaymarchFields),
            .create = [] { return std::make_unique<RaymarchTechnique>(); },
            .benchRows = [](const ParticleSet&, const std::vector<glm::dvec3>&) {
                return std::vector<BenchRow>{{"raymarch", {{"mode", "raymarch"}}},
                                             {"raymarch media_scale=0.5", {{"mode", "raymarch"}, {"media_scale", "0.5"}}},
                                             {"raymarch voxels=48", {{"mode", "raymarch"}, {"voxels", "48"}}},
                                             {"raymarch raymarch_steps=64", {{"mode", "raymarch"}, {"raymarch_steps", "64"}}}};
            }};
}

}  // namespace nimbus::media
