// mini_host: a second host engine for the media plugin, sharing nothing with Nimbus's engine but
// the small GL part. Renders one glTF scene headless at one time and writes EXR.
//   exit 0: written; 1: the scene, the GL context or the output failed; 2: bad command line.
#include <cstdio>
#include <exception>

#include "cli.h"
#include "ecs/world.h"
#include "egl_context.h"
#include "media/media_module.h"
#include "modules/render_module.h"
#include "modules/transform_module.h"
#include "nimbus/media/media_settings.h"
#include "nimbus/media/technique.h"

int main(int argc, char** argv) {
    mini::Options options;
    try {
        options = mini::parseArguments(argc, argv);
    } catch (const mini::UsageError& e) {
        std::fprintf(stderr, "mini_host: %s (%s)\n", e.what(), mini::usage());
        return 2;
    }
    if (options.help) {
        std::printf("%s\n", mini::usage());
        return 0;
    }
    try {
        mini::EglContext context;  // outlives the world, whose singletons hold GL objects
        mini::ecs::World world;
        world.set(mini::SceneRequest{options.scene, options.time});
        world.set(mini::RenderRequest{options.width, options.height, options.out, options.mediaOut, options.standardDepth});
        // The tier's settings for the mode (an unknown mode is refused here, naming the modes).
        const nimbus::QualityTier tier = options.quality == "fast"       ? nimbus::QualityTier::Fast
                                         : options.quality == "balanced" ? nimbus::QualityTier::Balanced
                                                                         : nimbus::QualityTier::Exact;
        nimbus::media::MediaRenderSettings media = nimbus::media::mediaSettingsForTier(tier, nimbus::media::builtInTechniques(), options.mode);
        if (options.mediaScale > 0.0f) {
            media.mediaScale = options.mediaScale;
            media.mediaScaleAuto = false;
        }
        world.set(mini::MediaSettings{media});
        world.import<mini::TransformModule>();
        world.import<mini::MediaModule>();  // before the render module: its bounds feed render.gather
        world.import<mini::RenderModule>();
        world.progress();  // OnLoad → PostLoad → OnUpdate → PreStore → OnStore, once
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "mini_host: %s\n", e.what());
        return 1;
    }
}
