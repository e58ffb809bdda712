#pragma once
// A scene loaded into an App with every plugin, simulated to the requested time. The render,
// reference, bench and edit commands all start from one, so they all see the same state.
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "nimbus/assets/image_io.h"
#include "nimbus/assets/scene.h"
#include "nimbus/ecs/app.h"
#include "nimbus/media/particle_set.h"
#include "nimbus/media/technique.h"
#include "nimbus/media/reference/reference_renderer.h"

namespace nimbus::sandbox {

struct SessionOptions {
    std::filesystem::path scene;
    double time = 0.0;
    std::vector<std::string> settings;  // KEY=VALUE from --set
    std::vector<std::pair<std::string, std::string>> options;  // (KEY=VALUE, origin) from options such as --mode
    std::optional<media::TechniqueTable> techniques;  // the media modes offered; empty: the built-in ones
    std::optional<assets::Scattering> scattering;      // the optical model instead of the scene's (--scattering)
    std::string defaultQuality;  // the tier unless the command line or the scene chose one; empty: exact
    // A key set where it has no effect is refused (media::ecs::refuseIdleSettings); false for a
    // caller that changes the tier itself and checks (the --budget-ms walk).
    bool refuseIdle = true;
};

// "single" or "multiple" (--scattering); InputError naming `option` otherwise.
assets::Scattering parseScattering(const std::string& text, const std::string& option = "--scattering");

class Session {
public:
    // Loads and validates the whole scene (throws InputError before anything is spawned), builds
    // the plugins, spawns the scene, refuses settings that would have no effect, and simulates it
    // to options.time (announced on stderr, with progress on a terminal, when it is long).
    explicit Session(const SessionOptions& options);
    // The same for a scene already loaded (the editor loads each edit from memory); options.scene
    // is not read.
    Session(std::shared_ptr<const assets::Scene> scene, const SessionOptions& options);

    // Takes over `previous`'s renderers (compiled programs, pooled targets), so a session rebuilt
    // for each edit does not recompile every shader. The images do not depend on it.
    void adoptRenderers(Session& previous);

    ecs::App& app() { return *app_; }
    const assets::Scene& scene() const { return *scene_; }
    std::shared_ptr<const assets::Scene> sharedScene() const { return scene_; }
    double time() const;

    // One real-time frame of the current state at width×height through `camera` (empty: the
    // scene's first). Needs a current GL context that outlives the session. Rendering stays on.
    assets::RgbImage renderRealtime(int width, int height, const std::string& camera = "");
    // The same frame left in the renderer's output() for the caller to show (no read-back).
    void renderFrame(int width, int height, const std::string& camera = "");

private:
    std::shared_ptr<const assets::Scene> scene_;
    std::unique_ptr<ecs::App> app_;
};

// What the reference renderer needs for the session's current state: the same node poses, the
// same particles and the same camera rule as the real-time path. Owns what the inputs point to.
struct ReferenceScene {
    std::vector<glm::dmat4> world;
    media::ParticleSet particles;
    std::vector<media::Volume> volumes;
    media::reference::ReferenceInputs inputs;
};
// `cameraOverride`, when given, replaces the named camera (the editor's free camera).
std::unique_ptr<ReferenceScene> makeReferenceScene(Session& session, const std::string& camera, int width, int height,
                                                   const assets::ResolvedCamera* cameraOverride = nullptr);

// What `sandbox render`, the demo and the editor render at unless told otherwise: the quality tier
// a game would pick. Libraries and tests default to `exact`.
inline constexpr char kRenderDefaultQuality[] = "balanced";


// Parses "WxH" (1..16384 each); throws InputError naming the option otherwise.
void parseSize(const std::string& text, int& width, int& height, const std::string& option = "--size");

}  // namespace nimbus::sandbox
