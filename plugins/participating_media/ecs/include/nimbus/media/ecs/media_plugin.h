#pragma once
// The participating-media plugin for Nimbus's ECS: the thin adapter over the host-agnostic core.
// build() registers, in one place:
//   components  Medium, ParticleCloud, Emitter
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

#include "nimbus/base/settings.h"
#include "nimbus/ecs/app.h"
#include "nimbus/ecs/plugin.h"
#include "nimbus/media/emitter_simulation.h"
#include "nimbus/media/media_renderer.h"
#include "nimbus/media/nimbus/media_render_extension.h"
#include "nimbus/media/media_scene.h"
#include "nimbus/media/particle_set.h"
#include "nimbus/media/slice_plan.h"

namespace nimbus::media::ecs {

inline constexpr char kEmitSystem[] = "media.emit";

// The quality tiers (the `quality` setting, `sandbox render --quality`): each is a set of other
// settings, which anything set explicitly overrides. `exact` is every per-fragment correction;
// `balanced` and `fast` light each particle once per frame and touch fragments only for opacity.
struct QualityPreset {
    const char* name;
    std::vector<std::pair<std::string, std::string>> settings;
};
inline const QualityPreset kQualityPresets[] = {
    {"fast", {{"lighting", "particle"}, {"slice_deposit", "auto"}, {"slices", "16"}, {"slice_resolution", "auto"},
              {"slice_detail", "2"}, {"media_scale", "auto"}, {"pcf_radius", "0"}, {"shadow_map_size", "1024"}}},
    {"balanced", {{"lighting", "particle_exact"}, {"exact_near_lamps", "on"}, {"slice_deposit", "auto"},
                  {"slice_resolution", "auto"}, {"slice_detail", "4"}}},
    {"exact", {}},
};

// The quality ladder a frame budget walks (FrameBudget in nimbus/base/frame_budget.h), from the
// lowest error to the fastest, as `sandbox bench` orders them by the error it measures (its rows
// carry these names): the tiers, with the media pass's resolution between them.
struct QualityRung {
    const char* name;
    std::vector<std::pair<std::string, std::string>> settings;
};
// Resolution steps of about 1.4× in pixels, so some rung lands within 1.25× of any budget the
// ladder spans.
inline const QualityRung kQualityLadder[] = {
    {"exact", {{"quality", "exact"}}},
    {"balanced", {{"quality", "balanced"}, {"media_scale", "1"}}},
    {"balanced media_scale=0.7", {{"quality", "balanced"}, {"media_scale", "0.7"}}},
    {"balanced media_scale=0.5", {{"quality", "balanced"}, {"media_scale", "0.5"}}},
    {"fast media_scale=1", {{"quality", "fast"}, {"media_scale", "1"}}},
    {"fast media_scale=0.85", {{"quality", "fast"}, {"media_scale", "0.85"}}},
    {"fast media_scale=0.7", {{"quality", "fast"}, {"media_scale", "0.7"}}},
    {"fast media_scale=0.6", {{"quality", "fast"}, {"media_scale", "0.6"}}},
    {"fast media_scale=0.5", {{"quality", "fast"}, {"media_scale", "0.5"}}},
    {"fast media_scale=0.35", {{"quality", "fast"}, {"media_scale", "0.35"}}},
    {"fast media_scale=0.25", {{"quality", "fast"}, {"media_scale", "0.25"}}},
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

// An emitter riding on the entity's transform. `previousWorld` is the transform at the start of the
// step, so particles born during a step spawn along the node's path, not in clumps.
struct EmitterComponent {
    EmitterSimulation simulation;
    glm::dmat4 previousWorld{1.0};
};

// Resource: the medium as it will be drawn this frame (world space), and how.
struct MediaFrame {
    ParticleSet particles;
    MediaRenderSettings settings;
};

// Resource: the real-time renderer; created on the first frame that has something to draw.
struct MediaRendererState {
    std::unique_ptr<MediaRenderer> renderer;
    std::unique_ptr<MediaRenderExtension> extension;  // the renderer in Nimbus's frame graph
};

class MediaPlugin final : public nimbus::ecs::Plugin {
public:
    std::string_view name() const override { return "nimbus.participating_media"; }
    void build(nimbus::ecs::App& app) override;
};

// The media renderer's settings a Settings resource fixes (directly or through the quality
// preset); InputError naming where a bad value came from.
MediaRenderSettings readMediaSettings(const Settings* settings);

// Gathers the particle set the renderers draw from the ECS state (also what `sandbox reference`
// renders, so both see exactly the same particles).
void gatherParticles(nimbus::ecs::World& world, ParticleSet& out);

}  // namespace nimbus::media::ecs
