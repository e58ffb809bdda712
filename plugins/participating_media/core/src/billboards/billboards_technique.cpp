#include "billboards/billboards_technique.h"

#include "billboards/billboard_pass.h"
#include "common/shared_frame.h"

namespace nimbus::media {
namespace {

class BillboardsTechnique final : public MediaTechnique {
public:
    void upload(TechniqueFrame& frame, const GraphFrame& context) override {
        frame.shared->buffer->sortBackToFront(*frame.particles, context.host.camera);
    }
    void addLightSlices(gpu::FrameGraph&, GraphFrame&, TechniqueFrame&) override {}  // unshadowed sprites
    gpu::ResourceHandle addMedia(gpu::FrameGraph& graph, GraphFrame& context, TechniqueFrame& frame) override {
        if (!pass_) pass_ = std::make_unique<BillboardPass>();
        return pass_->add(graph, context, *frame.shared->buffer, frame.shared->target);
    }

private:
    std::unique_ptr<BillboardPass> pass_;
};

}  // namespace

TechniqueEntry billboardsTechnique() {
    return {.name = "billboards",
            .help = "the game-industry yardstick: flat, sorted sprites lit per particle, with no volumetric or mesh shadows",
            .lightSlices = false,
            .multipleScattering = false,
            .drawsOver = true,
            .withinMedium = true,
            .read = [](const Settings&, QualityTier) -> std::any { return {}; },
            .create = [] { return std::make_unique<BillboardsTechnique>(); },
            .benchRows = [](const ParticleSet&, const std::vector<glm::dvec3>&) {
                return std::vector<BenchRow>{{"billboards", {{"mode", "billboards"}}}};
            }};
}

}  // namespace nimbus::media
