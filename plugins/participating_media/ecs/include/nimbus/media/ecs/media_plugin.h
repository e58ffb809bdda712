#pragma once
// The participating-media plugin for Nimbus's ECS: the thin adapter over the host-agnostic core.
// build() registers, in one place:
//   components  Medium, ParticleCloud, Volume, Emitter
//   Simulate    media.emit          steps every emitter with its node's transform at both step ends
//   Prepare     media.light_slices  gathers the particle set and plans the light slices
//   Render      media.render        hands the frame to the MediaRenderer (through MediaRenderExtension)
// and a scene spawner that reads each node's NIMBUS_participating_media object.
// Every system returns at once, allocating nothing, when no entity has its components.
#include <memory>
#include <string>
#include <utility>
#include <string_view>
#include <vector>

#include "nimbus/base/quality_tier.h"
#include "nimbus/base/settings.h"
#include "nimbus/ecs/app.h"
#include "nimbus/ecs/plugin.h"
#include "nimbus/media/emitter_simulation.h"
#include "nimbus/media/media_renderer.h"
#include "nimbus/media/technique.h"
#include "nimbus/media/nimbus/media_render_extension.h"
#include "nimbus/media/media_scene.h"
#include "nimbus/media/particle_set.h"
#include "nimbus/media/slice_plan.h"
#include "nimbus/media/volume.h"

namespace nimbus::media::ecs {

inline constexpr char kEmitSystem[] = "media.emit";

// The quality ladder a frame budget walks (FrameBudget in nimbus/base/frame_budget.h), from the
// lowest error to the fastest, as `sandbox bench` orders them by the error it measures (its rows
// carry these names): the tiers, with the media pass's resolution between them. Resolution steps
// of about 1.4× in pixels, so some rung lands within 1.25× of any budget the ladder spans.
struct QualityRung {
    const char* name;
    QualityTier tier;
    float mediaScale;  // 0: the tier's own
    // The rung as settings: quality, and media_scale where the rung fixes it.
    std::vector<std::pair<std::string, std::string>> assignments() const;
};
inline const QualityRung kQualityLadder[] = {
    {"exact", QualityTier::Exact, 0.0f},
    {"balanced", QualityTier::Balanced, 1.0f},
    {"balanced media_scale=0.7", QualityTier::Balanced, 0.7f},
    {"balanced media_scale=0.5", QualityTier::Balanced, 0.5f},
    {"fast media_scale=1", QualityTier::Fast, 1.0f},
    {"fast media_scale=0.85", QualityTier::Fast, 0.85f},
    {"fast media_scale=0.7", QualityTier::Fast, 0.7f},
    {"fast media_scale=0.6", QualityTier::Fast, 0.6f},
    {"fast media_scale=0.5", QualityTier::Fast, 0.5f},
    {"fast media_scale=0.35", QualityTier::Fast, 0.35f},
    {"fast media_scale=0.25", QualityTier::Fast, 0.25f},
};
inline constexpr char kLightSliceSystem[] = "media.light_slices";
inline constexpr char kRenderSystem[] = "media.render";

struct MediumComponent {
    Medium medium;
};

// A static cloud in the entity's local frame (the node's world transform applies).
struct ParticleCloud {
    std::vector<glm::vec3> positions;
    std::vector<float> radii;
    std::vector<float> densities;
};

// A volume of the medium in the entity's frame (volume.h); `origin` names its node in messages.
struct VolumeComponent {
    VolumeDesc desc;
    std::string origin;
};

// An emitter riding on the entity's transform. `previousWorld` is the transform at the start of the
// step, so particles born during a step spawn along the node's path, not in clumps.
struct EmitterComponent {
    EmitterSimulation simulation;
    glm::dmat4 previousWorld{1.0};
};

// Resource: the medium as it will be drawn this frame (world space), and how.
struct MediaFrame {
    ParticleSet particles;
    std::vector<Volume> volumes;
    MediaRenderSettings settings;
};

// Resource: the modes the renderer offers (the plugin's table, or the one it was built with).
struct MediaTechniques {
    TechniqueTable table;
};

// Resource: the real-time renderer; created on the first frame that has something to draw.
struct MediaRendererState {
    std::unique_ptr<MediaRenderer> renderer;
    std::unique_ptr<MediaRenderExtension> extension;  // the renderer in Nimbus's frame graph
};

class MediaPlugin final : public nimbus::ecs::Plugin {
public:
    // `techniques`: the modes to offer (a host or a test may add its own to the built-in ones).
    explicit MediaPlugin(TechniqueTable techniques = builtInTechniques()) : techniques_(std::move(techniques)) {}
    std::string_view name() const override { return "nimbus.participating_media"; }
    void build(nimbus::ecs::App& app) override;

private:
    TechniqueTable techniques_;
};

// The media renderer's settings a Settings resource fixes (directly or through the quality
// tier), with the modes of `techniques` (null: the built-in ones); InputError naming where a bad
// value came from.
MediaRenderSettings readMediaSettings(const Settings* settings, const TechniqueTable* techniques = nullptr);
// The same with the App's own table (MediaTechniques).
MediaRenderSettings readMediaSettings(nimbus::ecs::World& world);

// Refuses (InputError naming where it came from) a key the user set that has no effect on the
// frames the World's settings and scene would draw (media::idleSettings); one a scene's render
// block set as a default is logged as a warning instead, since the scene does not know the tier
// it will be drawn in. A host calls it once its settings and scene are in place.
void refuseIdleSettings(nimbus::ecs::World& world);

// Gathers the particle set the renderers draw from the ECS state (also what `sandbox reference`
// renders, so both see exactly the same particles).
void gatherParticles(nimbus::ecs::World& world, ParticleSet& out);
// The same for the volumes, in node order, placed by their nodes' transforms.
void gatherVolumes(nimbus::ecs::World& world, std::vector<Volume>& out);

}  // namespace nimbus::media::ecs
