// sandbox compare A B [--json]
// How far image A is from image B (B is usually the reference), in the metrics of
// nimbus/media/reference/image_metrics.h. --json prints exactly
// {"rel_rmse", "psnr", "p99_abs", "nonfinite"} (null for a metric that is undefined).
// A missing or unreadable file or a size mismatch exits non-zero with the reason on stderr.
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "commands.h"
#include "nimbus/assets/image_io.h"
#include "nimbus/base/error.h"
#include "nimbus/media/reference/image_metrics.h"

namespace nimbus::sandbox {
namespace {

struct CompareOptions {
    std::string a, b;
    bool json = false;
};

nlohmann::json number(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

std::string text(double v, const char* format) {
    if (std::isnan(v)) return "n/a";
    if (std::isinf(v)) return "inf";
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, format, v);
    return buffer;
}

int run(const CompareOptions& o) {
    const assets::RgbImage a = assets::readImage(o.a);
    const assets::RgbImage b = assets::readImage(o.b);
    media::reference::ImageMetrics m;
    try {
        m = media::reference::compareImages(a, b);
    } catch (const std::invalid_argument& e) {
        throwInputError(o.a, "", "", std::string("cannot compare with ") + o.b + ": " + e.what());
    }
    if (o.json) {
        const nlohmann::json out = {{"rel_rmse", number(m.relRmse)}, {"psnr", number(m.psnr)},
                                    {"p99_abs", number(m.p99Abs)}, {"nonfinite", m.nonfinite}};
        std::printf("%s\n", out.dump().c_str());
        return 0;
    }
    std::printf("A: %s\nB: %s (%dx%d)\n", o.a.c_str(), o.b.c_str(), b.width, b.height);
    std::printf("  rel_rmse   %s   (RMSE of linear RGB / mean luminance of B)\n", text(m.relRmse, "%.6g").c_str());
    std::printf("  psnr       %s dB (sRGB-encoded, clamped to [0, 1]; 200 = identical)\n", text(m.psnr, "%.3f").c_str());
    std::printf("  p99_abs    %s   (99th percentile of |A - B|, linear)\n", text(m.p99Abs, "%.6g").c_str());
    std::printf("  nonfinite  %zu   (pixels of A with NaN or Inf)\n", m.nonfinite);
    return 0;
}

}  // namespace

CommandRunner addCompareCommand(CLI::App& app) {
    auto options = std::make_shared<CompareOptions>();
    auto* cmd = app.add_subcommand("compare", "error metrics of image A against image B (the reference)");
    cmd->add_option("a", options->a, "image to judge")->required();
    cmd->add_option("b", options->b, "reference image (same size)")->required();
    cmd->add_flag("--json", options->json, "print {\"rel_rmse\", \"psnr\", \"p99_abs\", \"nonfinite\"} as JSON");
    return [options] { return run(*options); };
}

}  // namespace nimbus::sandbox
