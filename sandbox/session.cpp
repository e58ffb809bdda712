#include "session.h"

#include <charconv>
#include <cstdio>

#include "nimbus/base/error.h"
#include "nimbus/base/progress.h"
#include "nimbus/base/settings.h"
#include "nimbus/assets/scene_queries.h"
#include "nimbus/media/ecs/media_plugin.h"
#include "nimbus/media/media_renderer.h"
#include "nimbus/render/render_plugin.h"
#include "nimbus/scene/scene_plugin.h"

namespace nimbus::sandbox {

Session::Session(const SessionOptions& options)
    : Session(std::make_shared<const assets::Scene>(assets::loadScene(options.scene)), options) {}

namespace {

// Simulations longer than this many steps (a minute of scene time at 1/60 s) say so on stderr
// and draw a progress bar on a terminal: at about a millisecond a step, they take a while.
constexpr std::uint64_t kAnnouncedSteps = 3600;

void simulateAnnounced(ecs::App& app, double time) {
    const std::uint64_t steps = scene::simulationSteps(time, app.timeStep());
    if (steps <= kAnnouncedSteps) return scene::simulateTo(app, time);
    std::fprintf(stderr, "simulating %llu steps of %s s to t = %s s\n", static_cast<unsigned long long>(steps),
                 formatSettingNumber(app.timeStep()).c_str(), formatSettingNumber(time).c_str());
    ProgressBar bar("simulating", steps);
    std::uint64_t shown = 0;
    scene::simulateTo(app, time, [&](std::uint64_t done, std::uint64_t) {
        bar.advance(done - shown);
        shown = done;
    });
}

// An option (--mode, --quality) and a --set of the same key must agree: which would win is not
// for the user to guess.
void assignOption(Settings& settings, const std::string& assignment, const std::string& origin) {
    const std::string key = assignment.substr(0, assignment.find('='));
    const std::string value = assignment.substr(key.size() + 1);
    if (const auto given = settings.text(key); given && *given != value)
        throwInputError(origin, value, "", "conflicts with " + settings.origin(key) + " " + key + "=" + *given + ": give one");
    settings.assign(assignment, origin);
}

// The scene as the options have it: another optical model makes a copy that differs in it alone.
std::shared_ptr<const assets::Scene> withModel(std::shared_ptr<const assets::Scene> scene, const SessionOptions& options) {
    if (!options.scattering || *options.scattering == scene->environment.scattering) return scene;
    auto copy = std::make_shared<assets::Scene>(*scene);
    copy->environment.scattering = *options.scattering;
    return copy;
}

}  // namespace

assets::Scattering parseScattering(const std::string& text, const std::string& option) {
    if (text == "multiple") return assets::Scattering::Multiple;
    if (text == "single") return assets::Scattering::Single;
    throwInputError(option, text, "", "unknown scattering model (known: multiple, single)");
}

Session::Session(std::shared_ptr<const assets::Scene> scene, const SessionOptions& options) : scene_(withModel(std::move(scene), options)) {
    app_ = std::make_unique<ecs::App>();
    app_->insertResource<Settings>();
    app_->addPlugin<render::RenderPlugin>();
    app_->addPlugin<media::ecs::MediaPlugin>(options.techniques ? *options.techniques : media::builtInTechniques());
    for (const auto& assignment : options.settings) app_->resource<Settings>().assign(assignment);
    for (const auto& [assignment, origin] : options.options) assignOption(app_->resource<Settings>(), assignment, origin);
    // Checked now, so a bad value is refused even for a scene the media plugin has nothing to draw in.
    (void)media::ecs::readMediaSettings(app_->world());
    (void)scene::simulationSteps(options.time, app_->timeStep());  // refused before the scene is spawned
    scene::spawnScene(app_->world(), scene_);
    // After the scene's render block, which wins over the sandbox's default tier.
    if (!options.defaultQuality.empty() && !app_->resource<Settings>().has("quality"))
        app_->resource<Settings>().set("quality", options.defaultQuality, "sandbox's default");
    if (options.refuseIdle) media::ecs::refuseIdleSettings(app_->world());
    simulateAnnounced(*app_, options.time);
}

void Session::adoptRenderers(Session& previous) {
    auto& scene = app_->resource<render::RendererState>();
    scene.renderer = std::move(previous.app().resource<render::RendererState>().renderer);
    auto& media = app_->resource<media::ecs::MediaRendererState>();
    auto& old = previous.app().resource<media::ecs::MediaRendererState>();
    media.renderer = std::move(old.renderer);
    media.extension = std::move(old.extension);
    if (media.renderer) media.renderer->forgetFrames();  // this session's frames do not follow the old one's
}

double Session::time() const { return scene::simulationTime(*app_); }

assets::RgbImage Session::renderRealtime(int width, int height, const std::string& camera) {
    renderFrame(width, height, camera);
    return app_->resource<render::RendererState>().renderer->readOutput();
}

void Session::renderFrame(int width, int height, const std::string& camera) {
    auto& request = app_->resource<render::RenderRequest>();
    request.enabled = true;
    request.settings.width = width;
    request.settings.height = height;
    request.camera = camera;
    app_->redraw();
}

std::unique_ptr<ReferenceScene> makeReferenceScene(Session& session, const std::string& camera, int width, int height,
                                                   const assets::ResolvedCamera* cameraOverride) {
    auto out = std::make_unique<ReferenceScene>();
    ecs::World& world = session.app().world();
    out->world = scene::currentWorldTransforms(world);
    media::ecs::gatherParticles(world, out->particles);
    media::ecs::gatherVolumes(world, out->volumes);
    // A synthesized camera frames what the real-time path frames: the meshes and the medium.
    assets::Aabb bounds = assets::meshBounds(session.scene(), out->world);
    bounds.extend(media::particleBounds(out->particles));
    bounds.extend(media::volumeBounds(out->volumes));
    out->inputs.scene = &session.scene();
    out->inputs.world = &out->world;
    out->inputs.camera = cameraOverride ? *cameraOverride
                                        : assets::resolveCamera(session.scene(), out->world, camera, bounds,
                                                                static_cast<double>(width) / height);
    out->inputs.lights = assets::resolveLights(session.scene(), out->world);
    out->inputs.particles = &out->particles;
    out->inputs.volumes = &out->volumes;
    return out;
}

void parseSize(const std::string& text, int& width, int& height, const std::string& option) {
    const auto x = text.find('x');
    auto parse = [&](std::string_view part, int& out) {
        const auto [end, ec] = std::from_chars(part.data(), part.data() + part.size(), out);
        return ec == std::errc() && end == part.data() + part.size() && out >= 1 && out <= 16384;
    };
    if (x == std::string::npos || !parse(std::string_view(text).substr(0, x), width) ||
        !parse(std::string_view(text).substr(x + 1), height))
        throwInputError(option, typedText(text), "", "expected WxH with each side in 1..16384, e.g. 1280x720");
}

}  // namespace nimbus::sandbox
