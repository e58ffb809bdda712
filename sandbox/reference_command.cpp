// sandbox reference SCENE --out F.exr [--size WxH] [--time T] [--camera NAME|INDEX] [--tolerance E] [--threads N]
//                         [--spp N] [--seed S] [--scattering single|multiple]
// Renders the ground truth of docs/design.md §2 on the CPU (plugins/participating_media/reference) and
// writes it as linear radiance (.exr; any other format OIIO writes is display-encoded). In the
// multiple-scattering model it also writes each pixel's standard error beside it (F.stderr.exr)
// and prints its mean.
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>

#include "cli_options.h"
#include "commands.h"
#include "nimbus/assets/image_io.h"
#include "nimbus/base/error.h"
#include "nimbus/base/log.h"
#include "nimbus/media/reference/reference_renderer.h"
#include "session.h"

namespace nimbus::sandbox {
namespace {

struct ReferenceOptions {
    std::string scene;
    std::string out;
    std::string size = "640x360";
    std::string time = "0";
    std::string camera;
    std::string tolerance = "0.0001";
    int threads = 0;
    int spp = 64;
    std::uint64_t seed = 1;
    std::string scattering;  // empty: the scene's
};

// F.exr → F.stderr.exr: where the standard error goes.
std::string standardErrorPath(const std::string& out) {
    const auto dot = out.rfind('.');
    return (dot == std::string::npos ? out : out.substr(0, dot)) + ".stderr" + (dot == std::string::npos ? "" : out.substr(dot));
}

int run(const ReferenceOptions& o) {
    int width = 0, height = 0;
    parseSize(o.size, width, height);
    const double time = parseTime(o.time);
    const double tolerance = parsePositive(o.tolerance, "--tolerance", 0.1);

    const auto start = std::chrono::steady_clock::now();
    // The same Session the real-time renderer starts from: the same simulation steps, node poses
    // and particle set, so `compare` measures the renderers and nothing else.
    SessionOptions options{o.scene, time, {}};
    if (!o.scattering.empty()) options.scattering = parseScattering(o.scattering);
    Session session(options);
    const auto reference = makeReferenceScene(session, o.camera, width, height);
    const media::reference::ReferenceInputs& inputs = reference->inputs;
    const media::ParticleSet& particles = reference->particles;

    media::reference::ReferenceSettings settings;
    settings.width = width;
    settings.height = height;
    settings.tolerance = tolerance;
    settings.threads = o.threads;
    settings.spp = o.spp;
    settings.seed = o.seed;
    media::reference::ReferenceStats stats;
    assets::RgbImage standardError;
    const assets::RgbImage image = media::reference::renderReference(inputs, settings, &stats, &standardError);
    assets::writeImage(o.out, image);
    if (stats.multiple) assets::writeImage(standardErrorPath(o.out), standardError);

    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("reference: %dx%d, %zu particles, camera %s, %.2f s (render %.2f s) -> %s\n", width, height,
                particles.size(), inputs.camera.name.c_str(), seconds, stats.seconds, o.out.c_str());
    if (stats.multiple)
        std::printf("reference: multiple scattering, %d paths per pixel: mean standard error %.4g (%.3g%% of the mean radiance %.4g) -> %s\n",
                    o.spp, stats.meanStandardError, stats.meanRadiance > 0.0 ? 100.0 * stats.meanStandardError / stats.meanRadiance : 0.0,
                    stats.meanRadiance, standardErrorPath(o.out).c_str());
    if (stats.unconvergedPixels > 0)
        log::warn("reference: " + std::to_string(stats.unconvergedPixels) +
                  " pixels stopped at the quadrature's depth bound before reaching the tolerance");
    return 0;
}

}  // namespace

CommandRunner addReferenceCommand(CLI::App& app) {
    auto options = std::make_shared<ReferenceOptions>();
    auto* cmd = app.add_subcommand("reference", "render the CPU ground truth (docs/design.md §2) of a scene");
    cmd->add_option("scene", options->scene, "glTF scene (.gltf or .glb)")->required();
    cmd->add_option("--out", options->out, "output image: .exr holds linear radiance")->required();
    cmd->add_option("--size", options->size, "image size WxH")->capture_default_str();
    addTimeOption(cmd, options->time, "scene time in seconds (animation, emitters)");
    cmd->add_option("--camera", options->camera, "camera: a camera or node name, or an index into the file's cameras; default: the scene's first");
    cmd->add_option("--tolerance", options->tolerance, "relative change at which the quadrature stops, in (0, 0.1]")->capture_default_str();
    cmd->add_option("--threads", options->threads, "worker threads (0: all cores)")->capture_default_str()->check(CLI::Range(0, 1024));
    cmd->add_option("--spp", options->spp, "multiple scattering: paths per pixel")->capture_default_str()->check(CLI::Range(1, 1 << 20));
    cmd->add_option("--seed", options->seed, "multiple scattering: the paths' random streams")->capture_default_str();
    cmd->add_option("--scattering", options->scattering, "the optical model instead of the scene's: single or multiple");
    return [options] { return run(*options); };
}

}  // namespace nimbus::sandbox
