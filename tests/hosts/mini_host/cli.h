#pragma once
// mini_host's command line: SCENE.gltf --out F.exr [--size WxH] [--time T] [--media-out M.exr]
// [--mode particles|blocks|billboards] [--media-scale S] [--depth reversed|standard]: mode and
// media scale fill the plugin's typed settings (MediaRenderSettings), the rest of which keep the
// plugin's defaults (its exact tier); --depth picks the convention of mini_host's own depth buffer.
#include <filesystem>
#include <stdexcept>
#include <string>

namespace mini {

class UsageError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct Options {
    std::filesystem::path scene;
    std::filesystem::path out;
    std::filesystem::path mediaOut;  // empty: not written
    int width = 1280, height = 720;
    double time = 0.0;
    std::string mode;         // empty: the plugin's default (particles)
    float mediaScale = 0.0f;  // 0: the tier's (exact: 1, fast: automatic)
    std::string quality = "exact";  // the media's tier (nimbus::media::mediaSettingsForTier)
    bool standardDepth = false;  // --depth standard: the opaque pass draws standard depth
    bool help = false;
};

// Throws UsageError with a one-line reason.
Options parseArguments(int argc, const char* const* argv);
const char* usage();

}  // namespace mini
