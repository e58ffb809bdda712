#include "sheets/sheets_technique.h"

#include <algorithm>
#include <cstdio>
#include <limits>

#include "common/shared_frame.h"
#include "nimbus/base/settings.h"
#include "nimbus/media/medium_footprint.h"
#include "particles/particle_lighting_pass.h"
#include "sheets/sheet_pass.h"
#include "sheets/sheet_plan.h"
#include "slices/particle_slices.h"

namespace nimbus::media {
namespace {

const SettingField<SheetsSettings> kSheetsFields[] = {
    {{.key = "sheet_spacing",
      .help = "metres between the sheets the medium is cut into, parallel to the image",
      .type = SettingType::Number,
      .min = 0.001,
      .max = 1000.0,
      .defaultValue = "half the median particle radius (fast: one radius), at most 256 sheets"},
     &setNumber<&SheetsSettings::spacing>},
    {{.key = "sheet_lighting",
      .help = "where the slabs are lit: per fragment over each slab (exact), per particle fitted across its billboard, or per "
              "particle with each of its rays shaded as a fragment",
      .type = SettingType::Choice,
      .words = {"fragment", "particle", "particle_exact"},
      .defaultValue = "fragment (balanced: particle_exact, fast: particle)"},
     &setChoice<&SheetsSettings::lighting>},
};

// The view depths the particles' spheres span, and the largest radius.
struct DepthSpan {
    double nearDepth = std::numeric_limits<double>::max(), farDepth = std::numeric_limits<double>::lowest();
    float maxRadius = 0.0f;
};

DepthSpan depthSpan(const ParticleSet& particles, const gpu::View& view) {
    DepthSpan span;
    for (std::size_t i = 0; i < particles.size(); ++i) {
        const double depth = glm::dot(particles.position[i] - view.origin, view.forward);
        span.nearDepth = std::min(span.nearDepth, depth - particles.radius[i]);
        span.farDepth = std::max(span.farDepth, depth + particles.radius[i]);
        span.maxRadius = std::max(span.maxRadius, particles.radius[i]);
    }
    return span;
}

class SheetsTechnique final : public MediaTechnique {
public:
    void upload(TechniqueFrame& frame, const GraphFrame& context) override {
        SharedFrame& shared = *frame.shared;
        const gpu::View& view = context.host.camera;
        shared.buffer->sortByViewDepth(*frame.particles, view);
        shared.buffer->uploadLampNeighbourhoods(*frame.particles, context.host.lights);
        const SheetsSettings own = techniqueSettings<SheetsSettings>(*frame.settings);
        const double spacing = own.spacing > 0.0f ? own.spacing : sheetSpacingFor(frame.particles->radius, own.spacingPerRadius, radii_);
        const DepthSpan span = depthSpan(*frame.particles, view);
        plan_ = planSheets(shared.buffer->rankDepths(), span.maxRadius, span.nearDepth, span.farDepth, view.znear, spacing);
        frame.report("sheets", static_cast<long long>(plan_.sheets.size()));
        frame.report("sheet_spacing", static_cast<double>(plan_.spacing));
        frame.report("sheet_spacing_widened", plan_.widened);
    }

    void addLightSlices(gpu::FrameGraph& graph, GraphFrame& context, TechniqueFrame& frame) override {
        slices_.add(graph, context, *frame.particles, *frame.shared, frame.settings->sliceDeposit);
    }

    gpu::ResourceHandle addMedia(gpu::FrameGraph& graph, GraphFrame& context, TechniqueFrame& frame) override {
        const SheetsSettings own = techniqueSettings<SheetsSettings>(*frame.settings);
        if (!sheetPass_) sheetPass_ = std::make_unique<SheetPass>();
        const SharedFrame& shared = *frame.shared;
        const FragmentLamps lamps = fragmentLamps(context.host.lights);
        frame.report("exact_lighting", own.lighting == SheetLighting::Fragment);
        if (own.lighting == SheetLighting::Fragment) {
            frame.report("constant_source", false);
            return sheetPass_->add(graph, context, *shared.buffer, nullptr, plan_, false, lamps, shared.target);
        }
        if (!lightingPass_) lightingPass_ = std::make_unique<ParticleLightingPass>();
        const gpu::View& v = context.host.camera;
        // As in `particles`: billboards of a few pixels have nothing for a fit to follow.
        const bool constant = shared.coverage * v.width * v.height < kConstantSplatPixels * static_cast<double>(frame.particles->size());
        frame.report("constant_source", constant);
        lightingPass_->add(graph, context, *shared.buffer, frame.particles->size(),
                           {.exact = own.lighting == SheetLighting::ParticleExact, .constant = constant}, lamps);
        return sheetPass_->add(graph, context, *shared.buffer, lightingPass_.get(), plan_, constant, lamps, shared.target);
    }

private:
    SheetPlan plan_;
    std::vector<float> radii_;  // sheetSpacingFor's scratch
    ParticleSlices slices_;
    std::unique_ptr<ParticleLightingPass> lightingPass_;
    std::unique_ptr<SheetPass> sheetPass_;
};

// The tiers, a halved media target, and the spacing at twice and half the default's (one and a
// quarter of the median radius), written in metres as a user would set it.
std::vector<BenchRow> sheetBenchRows(const ParticleSet& particles, const std::vector<glm::dvec3>&) {
    std::vector<BenchRow> rows{{"sheets", {{"mode", "sheets"}}},
                               {"sheets quality=fast", {{"mode", "sheets"}, {"quality", "fast"}}},
                               {"sheets media_scale=0.5", {{"mode", "sheets"}, {"media_scale", "0.5"}}}};
    std::vector<float> scratch;
    for (const double perRadius : {1.0, 0.25}) {
        const double spacing = std::max(0.001, sheetSpacingFor(particles.radius, perRadius, scratch));  // the setting's minimum
        char metres[32];
        std::snprintf(metres, sizeof metres, "%.3g", spacing);
        rows.push_back({std::string("sheets sheet_spacing=") + metres, {{"mode", "sheets"}, {"sheet_spacing", metres}}});
    }
    return rows;
}

}  // namespace

SheetsSettings SheetsSettings::forTier(QualityTier tier) {
    SheetsSettings s;
    if (tier == QualityTier::Balanced) s.lighting = SheetLighting::ParticleExact;
    if (tier == QualityTier::Fast) {
        s.spacingPerRadius = 1.0f;
        s.lighting = SheetLighting::Particle;
    }
    return s;
}

TechniqueEntry sheetsTechnique() {
    return {.name = "sheets",
            .help = "image-aligned sheet-buffer splatting: pre-integrated kernel slabs summed per sheet, sheets composited back "
                    "to front, so no order flips as the view turns",
            .sliceDeposit = true,
            .withinMedium = true,
            .settings = specsOf(kSheetsFields),
            .read = readerOf(kSheetsFields),
            .create = [] { return std::make_unique<SheetsTechnique>(); },
            .benchRows = sheetBenchRows};
}

}  // namespace nimbus::media
