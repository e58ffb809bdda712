#include "particles/particles_technique.h"

#include <algorithm>
#include <iterator>
#include <optional>

#include "common/shared_frame.h"
#include "nimbus/base/settings.h"
#include "nimbus/media/medium_footprint.h"
#include "particles/particle_lighting_pass.h"
#include "particles/particle_pass.h"
#include "particles/particle_splat_edges_pass.h"
#include "particles/particle_splat_pass.h"
#include "slices/particle_slices.h"

namespace nimbus::media {
namespace {

bool perFragmentLighting(const ParticlesSettings& s) { return s.lighting == ParticleLighting::Fragment; }
bool perParticleLighting(const ParticlesSettings& s) { return s.lighting != ParticleLighting::Fragment; }

const SettingField<ParticlesSettings> kParticlesFields[] = {
    {{.key = "lighting",
      .help = "where light is evaluated: per fragment (exact), per particle fitted across its billboard, or per particle "
              "with each of its rays shaded as a fragment",
      .type = SettingType::Choice,
      .words = {"fragment", "particle", "particle_exact"},
      .defaultValue = "fragment (balanced: particle_exact, fast: particle)"},
     &setChoice<&ParticlesSettings::lighting>},
    {{.key = "exact_near_lamps",
      .help = "with per-particle lighting: shade per fragment while a point or spot light lies inside the medium (a "
              "particle with a central column over 0.1)",
      .type = SettingType::Boolean,
      .defaultValue = "off",
      .actsWhen = "with lighting=particle or particle_exact",
      .showsWith = "a point or spot light inside the medium"},
     &setBoolean<&ParticlesSettings::exactNearLamps>, &perParticleLighting},
    {{.key = "cut_lighting",
      .help = "with per-particle lighting, the particles a mesh's box enters (not a box that spans the medium, such as a "
              "ground): lit per fragment as the exact tier lights them, over the whole particle or only on the rays a "
              "surface may cut inside it (where the scene depth is a depth test; the fit elsewhere), or by the fit, which "
              "carries light across the mesh",
      .type = SettingType::Choice,
      .words = {"particles", "rays", "off"},
      .defaultValue = "particles (fast: off)",
      .actsWhen = "with lighting=particle or particle_exact",
      .showsWith = "a mesh inside the medium, in a frame without a point or spot light"},
     &setChoice<&ParticlesSettings::cutLighting>, &perParticleLighting},
    // The two below are the per-fragment pass's; frames exact_near_lamps shades per fragment keep
    // their defaults.
    {{.key = "soft_particles",
      .help = "clip each particle's kernel at opaque surfaces (off: the billboard plane test)",
      .type = SettingType::Boolean,
      .defaultValue = "on",
      .actsWhen = "with lighting=fragment"},
     &setBoolean<&ParticlesSettings::softParticles>, &perFragmentLighting},
    {{.key = "layer_light",
      .help = "integrate the light's transmittance over each particle (off: at one point, faster)",
      .type = SettingType::Boolean,
      .defaultValue = "on",
      .actsWhen = "with lighting=fragment"},
     &setBoolean<&ParticlesSettings::layerLight>, &perFragmentLighting},
};

// Balanced takes the sun's mesh visibility per fragment on the particles a mesh crosses
// (splat_source.glsl), in runs of the draw order near a mesh's box. The lighting pass flags a
// particle only where the occluder lies within half a radius of a shading point, so within 1.5
// radii of its centre: two radii leave room for the shadow map's texels.
constexpr double kCrossingReach = 2.0;

// Per particle, the splat variant it is drawn with (SplatFlag bits): within kLampReach of a lamp its
// fragments take the lamp's light; the lighting pass's fit carries it for the others. Lamps per
// fragment cost every fragment of the particles drawn with them (llvmpipe), so only those take them.
std::vector<std::uint8_t> splatFlags(const std::vector<std::uint8_t>& nearMesh, const ParticleSet& particles,
                                     const std::vector<Light>& lights, const FragmentLamps& lamps) {
    std::vector<std::uint8_t> flags = lamps.lamps[0] >= 0 ? particlesNearLamps(particles, lights, lamps.lamps, kLampReach)
                                                           : std::vector<std::uint8_t>(particles.size(), 0);
    for (std::size_t i = 0; i < flags.size(); ++i)
        flags[i] = static_cast<std::uint8_t>((flags[i] != 0 ? kSplatNearLamp : 0) | (i < nearMesh.size() && nearMesh[i] != 0 ? kSplatNearMesh : 0));
    return flags;
}

// The particles a mesh's box enters: shaded per fragment as the exact tier shades them. Not for a
// box that spans the medium (a ground): it clips them as the fit's kernel table does, and lights
// what is seen of them evenly, and it would take most of a low cloud (cloud.gltf 379 of 500
// particles, its balanced frame 4.8 times as long).
void addMeshInside(std::vector<std::uint8_t>& flags, const std::vector<OccluderBox>& meshes, const ParticleSet& particles,
                   const Aabb& bounds) {
    std::vector<OccluderBox> within;
    std::copy_if(meshes.begin(), meshes.end(), std::back_inserter(within), [&](const OccluderBox& box) { return !boxSpansMedium(box, bounds); });
    const std::vector<std::uint8_t> inside = particlesNearMeshes(within, particles, 1.0);
    for (std::size_t i = 0; i < flags.size(); ++i)
        if (inside[i] != 0) flags[i] |= kSplatMeshInside;
}

// At full resolution the splats may take the scene depth as their depth test's.
void addClearOfMeshes(std::vector<std::uint8_t>& flags, const std::vector<OccluderBox>& meshes, const ParticleSet& particles,
                      const gpu::View& view) {
    const std::vector<std::uint8_t> clear = particlesClearOfMeshes(meshes, particles, view);
    for (std::size_t i = 0; i < flags.size(); ++i)
        if (clear[i] != 0) flags[i] |= kSplatClearOfMeshes;
}

class ParticlesTechnique final : public MediaTechnique {
    // What this frame's splats drew with, for their redraw at the edges.
    struct SplatEdges {
        SplatVariant variant;
        std::vector<std::uint8_t> flags;
        FragmentLamps lamps;
        glm::ivec4 rect{0};
    };

public:
    void upload(TechniqueFrame& frame, const GraphFrame& context) override {
        SharedFrame& shared = *frame.shared;
        shared.buffer->sortBackToFront(*frame.particles, context.host.camera);
        shared.buffer->uploadLampNeighbourhoods(*frame.particles, context.host.lights);
    }

    void addLightSlices(gpu::FrameGraph& graph, GraphFrame& context, TechniqueFrame& frame) override {
        slices_.add(graph, context, *frame.particles, *frame.shared, frame.settings->sliceDeposit);
    }

    gpu::ResourceHandle addMedia(gpu::FrameGraph& graph, GraphFrame& context, TechniqueFrame& frame) override {
        const ParticlesSettings own = techniqueSettings<ParticlesSettings>(*frame.settings);
        const bool perParticle = own.lighting != ParticleLighting::Fragment &&
                                 !(own.exactNearLamps && lampInsideMedium(*frame.particles, context.host.lights));
        edges_.reset();
        return perParticle ? addPerParticle(graph, context, frame, own) : addPerFragment(graph, context, frame, own);
    }

    // The per-particle tiers redraw their splats at the edges where a mesh reaches into the medium;
    // the per-fragment pass does not.
    glm::ivec4 edgeRect() const override { return edges_ ? edges_->rect : glm::ivec4(0); }

    gpu::ResourceHandle addEdges(gpu::FrameGraph& graph, GraphFrame& context, TechniqueFrame& frame, const EdgeTarget& target) override {
        if (!edges_) return {};
        return addParticleSplatEdges(graph, context, *splatPass_, *frame.shared->buffer, *lightingPass_,
                                     {edges_->variant, edges_->flags, billboardsMeeting(*frame.particles, context.host.camera, target.rect), edges_->lamps},
                                     target);
    }

private:
    gpu::ResourceHandle addPerParticle(gpu::FrameGraph& graph, GraphFrame& context, TechniqueFrame& frame,
                                       const ParticlesSettings& own) {
        if (!lightingPass_) lightingPass_ = std::make_unique<ParticleLightingPass>();
        if (!splatPass_) splatPass_ = std::make_unique<ParticleSplatPass>();
        const SharedFrame& shared = *frame.shared;
        const gpu::View& v = context.host.camera;
        const FragmentLamps lamps = fragmentLamps(context.host.lights);
        // Billboards of a few pixels: a fit across them has nothing to follow, and at 10⁶ particles
        // its nine rays and varyings cost more than the pixels.
        const bool constant = shared.coverage * v.width * v.height < kConstantSplatPixels * static_cast<double>(frame.particles->size());
        const bool exact = own.lighting == ParticleLighting::ParticleExact;
        std::vector<std::uint8_t> nearMesh;
        if (exact && !constant && lamps.sun >= 0 && context.shadowMap.valid() && !context.host.occluders.empty())
            nearMesh = particlesNearMeshes(context.host.occluders, *frame.particles, kCrossingReach);
        const bool crossings = std::any_of(nearMesh.begin(), nearMesh.end(), [](std::uint8_t n) { return n != 0; });
        const bool lampRuns = lamps.lamps[0] >= 0;
        std::vector<std::uint8_t> flags = splatFlags(nearMesh, *frame.particles, context.host.lights, lamps);
        if (context.host.occludersComplete && shared.target.size == glm::ivec2(v.width, v.height))
            addClearOfMeshes(flags, context.host.occluders, *frame.particles, v);
        // Not with a point or spot light: the exact program would take its near field for every
        // fragment of those particles (campfire balanced 99 -> 141 ms at 1280x720, 11 particles).
        if (own.cutLighting != CutLighting::Off && !constant && !lampRuns && !context.host.occluders.empty())
            addMeshInside(flags, context.host.occluders, *frame.particles, shared.bounds);
        const long long inside = std::count_if(flags.begin(), flags.end(), [](std::uint8_t f) { return (f & kSplatMeshInside) != 0; });
        frame.report("exact_lighting", false);
        frame.report("constant_source", constant);
        frame.report("mesh_crossings", crossings);
        frame.report("mesh_inside_particles", inside);
        frame.report("lamp_particles", static_cast<long long>(std::count_if(flags.begin(), flags.end(), [](std::uint8_t f) {
                                           return (f & kSplatNearLamp) != 0;
                                       })));
        frame.report("depth_tested_particles", static_cast<long long>(std::count_if(flags.begin(), flags.end(), [](std::uint8_t f) {
                                                   return (f & kSplatClearOfMeshes) != 0;
                                               })));
        lightingPass_->add(graph, context, *shared.buffer, frame.particles->size(),
                           {.exact = exact, .constant = constant, .meshCrossings = crossings, .lampRuns = lampRuns}, lamps, flags);
        const SplatVariant variant{.eyeInside = eyeInsideMedium(*frame.particles, v),
                                   .constant = constant,
                                   .meshCrossings = crossings,
                                   .meshInside = inside > 0,
                                   .cutRays = own.cutLighting == CutLighting::Rays};
        if (!frame.settings->upsampleOnly && !constant) planEdges(context, frame, {variant, flags, lamps});
        frame.report("edge_pixels", static_cast<long long>(edges_ ? edges_->rect.z * edges_->rect.w : 0));
        return splatPass_->add(graph, context, *shared.buffer, *lightingPass_, variant, std::move(flags), lamps, shared.target);
    }

    // Mixed resolution where a mesh reaches into the medium: its silhouette and cut there need
    // their own pixels (a thin wing has no reduced texel at its depth). Kept without one too: the
    // renderer may redraw a lamp's peak (MediaTarget::peak).
    void planEdges(const GraphFrame& context, const TechniqueFrame& frame, SplatEdges edges) {
        edges.rect = meshEdgeRect(context.host.occluders, *frame.particles, context.host.camera, frame.shared->target.size);
        edges_ = std::move(edges);
    }

    gpu::ResourceHandle addPerFragment(gpu::FrameGraph& graph, GraphFrame& context, TechniqueFrame& frame,
                                       const ParticlesSettings& own) {
        frame.report("exact_lighting", true);
        frame.report("constant_source", false);
        if (!particlePass_) particlePass_ = std::make_unique<ParticlePass>();
        return particlePass_->add(graph, context, *frame.shared->buffer, {own.softParticles, own.layerLight}, frame.shared->target);
    }

    ParticleSlices slices_;
    std::optional<SplatEdges> edges_;
    std::unique_ptr<ParticlePass> particlePass_;  // each made when first needed
    std::unique_ptr<ParticleLightingPass> lightingPass_;
    std::unique_ptr<ParticleSplatPass> splatPass_;
};

}  // namespace

ParticlesSettings ParticlesSettings::forTier(QualityTier tier) {
    ParticlesSettings s;
    if (tier == QualityTier::Fast) {
        s.lighting = ParticleLighting::Particle;
        s.cutLighting = CutLighting::Off;  // it doubled cumulus_aircraft's fast frame (docs/design-notes.md)
    }
    if (tier == QualityTier::Balanced) s.lighting = ParticleLighting::ParticleExact;
    return s;
}

TechniqueEntry particlesTechnique() {
    return {.name = "particles",
            .help = "sorted soft billboards, each a closed-form slab of its kernel lit through the light slices",
            .sliceDeposit = true,
            .sliceCrops = true,
            .edges = true,
            .lampPeaks = true,  // campfire fast at ¼: 4.7% (4.4% at full resolution)
            .drawsOver = true,
            .withinMedium = true,
            .settings = specsOf(kParticlesFields),
            // Where a mesh reaches into the medium, balanced takes finer slices: with the particles
            // a mesh enters lit per fragment (cut_lighting), the light the mesh cuts in the medium
            // is what is left of its seam band's error (docs/design-notes.md).
            .sharedDefaults =
                [](MediaRenderSettings& s, QualityTier tier) {
                    if (tier == QualityTier::Balanced) s.sliceTexelsPerRadiusNearMeshes = 6.0f;
                },
            .read = readerOf(kParticlesFields),
            .idle =
                [](const std::any& read, const MediaRenderSettings& shared) {
                    std::vector<std::string> idle = idleOf(kParticlesFields)(read, shared);
                    // The per-fragment pass draws no edges again.
                    if (std::any_cast<const ParticlesSettings&>(read).lighting == ParticleLighting::Fragment) idle.push_back("mixed_resolution");
                    return idle;
                },
            .create = [] { return std::make_unique<ParticlesTechnique>(); },
            .benchRows = [](const ParticleSet&, const std::vector<glm::dvec3>&) {
                std::vector<BenchRow> rows{{"particles", {{"mode", "particles"}}}};
                for (const char* slices : {"4", "8", "16", "32"})
                    rows.push_back({std::string("particles slices=") + slices, {{"mode", "particles"}, {"slices", slices}}});
                rows.push_back({"particles layer_light=off", {{"mode", "particles"}, {"layer_light", "off"}}});
                rows.push_back({"particles media_scale=0.5", {{"mode", "particles"}, {"media_scale", "0.5"}}});
                rows.push_back({"particles media_scale=0.25", {{"mode", "particles"}, {"media_scale", "0.25"}}});
                return rows;
            },
            .scalingBench = true};
}

}  // namespace nimbus::media
