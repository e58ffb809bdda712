// The real-time multiple-scattering model (common/environment_grid.h, common/diffusion.h) against
// the judge's multiple scattering, stored at 96×54 with 128 or 256 paths per pixel and each
// pixel's standard error (tests/data/multiple_scattering/make_references.sh). rel-RMSE as the
// content tests measure it, less the judge's own noise in quadrature (its per-pixel standard
// errors, RMS, over its mean: 1–4 %), so the bound is on the error against the model, not against
// one noisy estimate of it. Each bound is the 10 % or about 1.25 × what was measured when it
// was set, whichever is lower; on the dense clouds the real-time model must also err well below what
// the single-scattering frame errs against the same image (docs/design-notes.md: the fit).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <unistd.h>
#include <ostream>
#include <string>
#include <vector>

#include "media_test_support.h"
#include "nimbus/base/settings.h"
#include "nimbus/media/ecs/media_plugin.h"
#include "nimbus/render/render_plugin.h"
#include <nlohmann/json.hpp>

namespace nimbus::test::media {
namespace {

using Json = nlohmann::json;
constexpr int kWidth = 96, kHeight = 54;

struct MultipleCase {
    const char* scene;
    double time;
    const char* mode;
    const char* quality;
    double bound;
    double belowSingle;  // the real-time error at most this × the single-scattering frame's; 0: not checked
};

void PrintTo(const MultipleCase& c, std::ostream* os) { *os << c.scene << " " << c.mode << " " << c.quality; }

class MultipleVsJudge : public GlSceneTest, public ::testing::WithParamInterface<MultipleCase> {};

assets::RgbImage realtime(const MultipleCase& c, assets::Scattering model) {
    sandbox::Session session({.scene = contentScene(c.scene),
                              .time = c.time,
                              .settings = {std::string("mode=") + c.mode, std::string("quality=") + c.quality},
                              .scattering = model});
    return session.renderRealtime(kWidth, kHeight);
}

// The judge's own noise as rel-RMSE: its per-pixel standard errors, RMS over pixels and channels,
// over its mean luminance. An image equal to the expected value errs this much against the judge.
double judgeNoise(const assets::RgbImage& judge, const assets::RgbImage& standardError) {
    double squares = 0.0, mean = 0.0;
    for (std::size_t i = 0; i < judge.pixelCount(); ++i) {
        mean += luminance(glm::vec3(judge.rgb[3 * i], judge.rgb[3 * i + 1], judge.rgb[3 * i + 2]));
        for (int c = 0; c < 3; ++c) squares += static_cast<double>(standardError.rgb[3 * i + c]) * standardError.rgb[3 * i + c];
    }
    const double n = static_cast<double>(judge.pixelCount());
    return std::sqrt(squares / (3.0 * n)) / (mean / n);
}

// rel-RMSE against the judge less its noise (in quadrature): the error against the model itself.
double debiased(double relRmse, double noise) { return std::sqrt(std::max(0.0, relRmse * relRmse - noise * noise)); }

TEST_P(MultipleVsJudge, RelRmseWithinTheScenesBound) {
    const MultipleCase& c = GetParam();
    const std::filesystem::path folder = std::filesystem::path(NIMBUS_TEST_DATA_DIR) / "multiple_scattering";
    const assets::RgbImage judge = assets::readImage(folder / (std::string(c.scene) + ".exr"));
    const double noise = judgeNoise(judge, assets::readImage(folder / (std::string(c.scene) + ".stderr.exr")));
    const auto raw = nimbus::media::reference::compareImages(realtime(c, assets::Scattering::Multiple), judge);
    EXPECT_EQ(raw.nonfinite, 0u);
    const double multiple = debiased(raw.relRmse, noise);
    EXPECT_LE(multiple, c.bound) << c.scene << " " << c.mode << " " << c.quality;
    double single = 0.0;
    if (c.belowSingle > 0.0) {
        single = debiased(nimbus::media::reference::compareImages(realtime(c, assets::Scattering::Single), judge).relRmse, noise);
        EXPECT_LE(multiple, c.belowSingle * single) << c.scene << ": single scattering errs " << single;
    }
    RecordProperty("rel_rmse", std::to_string(multiple));
    std::printf("[ measured ] %s %s %s rel_rmse=%.4f (raw %.4f, judge noise %.4f, bound %.3f) single=%.4f\n", c.scene, c.mode, c.quality,
                multiple, raw.relRmse, noise, c.bound, single);
}

// scattering_warm_sweeps on a moving plume, as a game runs it: 30 frames of steam, each stepped
// 1/60 s, each frame's grid solved from the frame before's. The last frame stays near the cold
// solve's (its light lags the medium a little), and once the medium stops, the next frame is
// solved cold and is a cold session's, bit for bit.
TEST_F(GlSceneTest, AWarmStartedPlumeStaysNearTheColdFramesAndMeetsThemWhenItStops) {
    const auto play = [](const std::vector<std::string>& extra, std::vector<assets::RgbImage>& frames, bool& warm) {
        std::vector<std::string> settings{"mode=particles", "quality=fast"};
        settings.insert(settings.end(), extra.begin(), extra.end());
        sandbox::Session session({.scene = contentScene("steam"), .time = 8.0, .settings = settings});
        (void)session.renderRealtime(kWidth, kHeight);
        for (int i = 0; i < 30; ++i) session.app().update();
        const auto& media = session.app().world().resource<nimbus::media::ecs::MediaRendererState>();
        warm = media.renderer->stats().scatteringWarm;
        frames.push_back(session.app().resource<render::RendererState>().renderer->readOutput());
        frames.push_back(session.renderRealtime(kWidth, kHeight));  // the medium stopped
        EXPECT_FALSE(media.renderer->stats().scatteringWarm);
    };
    std::vector<assets::RgbImage> warmFrames, coldFrames;
    bool warm = false, cold = true;
    play({"scattering_warm_sweeps=16"}, warmFrames, warm);
    play({}, coldFrames, cold);
    EXPECT_TRUE(warm);
    EXPECT_FALSE(cold);
    const double moving = nimbus::media::reference::compareImages(warmFrames[0], coldFrames[0]).relRmse;
    std::printf("[ measured ] steam, 30 frames warm-started against cold: rel_rmse=%.4f\n", moving);
    EXPECT_GT(moving, 0.0) << "the last moving frame was solved from the one before";
    EXPECT_LT(moving, 0.015) << "its light lags the cold solve's by little (0.96% when the bound was set)";
    EXPECT_EQ(warmFrames[1].rgb, coldFrames[1].rgb);
}

// "Model only what a scene needs": unseen_thin_haze made dark (albedo 0.02) rescatters 0.7% of
// its first scattering's light, under the 1% at which the multiple model's grid is not read, and
// the frame is the single program's, bit for bit; at its own albedo (34%) the grid is read.
TEST_F(GlSceneTest, ADarkThinMediumSkipsTheMultipleTermByItsMeasure) {
    const std::filesystem::path folder = std::filesystem::temp_directory_path() / ("nimbus_dark_haze_" + std::to_string(::getpid()));
    std::filesystem::create_directories(folder);
    const std::filesystem::path source = mediaScene("unseen_thin_haze");
    Json doc = Json::parse(std::ifstream(source));
    for (Json& node : doc["nodes"])
        if (node.contains("extensions") && node["extensions"].contains("NIMBUS_participating_media"))
            node["extensions"]["NIMBUS_participating_media"]["medium"]["albedo"] = {0.02, 0.02, 0.02};
    std::ofstream(folder / "dark_haze.gltf") << doc.dump();
    std::filesystem::copy_file(source.parent_path() / "unseen_thin_haze.bin", folder / "unseen_thin_haze.bin");
    struct Frame {
        assets::RgbImage image;
        nimbus::media::MediaFrameStats stats;
    };
    const auto render = [](const std::filesystem::path& scene, assets::Scattering model) {
        sandbox::Session session({.scene = scene, .settings = {"mode=particles"}, .scattering = model});
        Frame f{session.renderRealtime(kWidth, kHeight), {}};
        f.stats = session.app().world().resource<nimbus::media::ecs::MediaRendererState>().renderer->stats();
        return f;
    };
    const Frame dark = render(folder / "dark_haze.gltf", assets::Scattering::Multiple);
    EXPECT_FALSE(dark.stats.multipleScattering) << "rescatters " << dark.stats.rescatter;
    EXPECT_LT(dark.stats.rescatter, 0.01f);
    EXPECT_GT(dark.stats.rescatter, 0.0f);
    EXPECT_EQ(dark.image.rgb, render(folder / "dark_haze.gltf", assets::Scattering::Single).image.rgb);
    const Frame bright = render(source, assets::Scattering::Multiple);
    EXPECT_TRUE(bright.stats.multipleScattering);
    EXPECT_GT(bright.stats.rescatter, 0.2f);
    std::printf("[ measured ] rescattered share: dark haze %.4f, haze %.4f\n", dark.stats.rescatter, bright.stats.rescatter);
    std::filesystem::remove_all(folder);
}

INSTANTIATE_TEST_SUITE_P(
    Content, MultipleVsJudge,
    ::testing::Values(
        MultipleCase{"cumulus", 0.0, "particles", "balanced", 0.026, 0.28},  // 2.1 %, single 10.4 %
        // 2.1 %, single 10.4 %. At 96x54 fast's billboards are too small for a reduced media
        // target, which gave 4.3 % when media_scale=auto still took ½ for them.
        MultipleCase{"cumulus", 0.0, "particles", "fast", 0.026, 0.28},
        MultipleCase{"cumulus", 0.0, "raymarch", "balanced", 0.027, 0.0},  // 2.1 %
        MultipleCase{"cumulus", 0.0, "blocks", "balanced", 0.024, 0.0},  // 1.9 %
        MultipleCase{"cumulus", 0.0, "sheets", "balanced", 0.027, 0.0},  // 2.1 %
        // The meshes are walls to the grid's light (diffusion.h), as the model's meshes absorb what
        // reaches them: cumulus_aircraft 3.0x below single scattering (it was 2.0x), cloud 2.9x (2.4x).
        MultipleCase{"cloud", 0.0, "particles", "balanced", 0.041, 0.36},  // 3.3 %, single 9.4 %
        MultipleCase{"cloud", 0.0, "raymarch", "balanced", 0.041, 0.0},  // 3.3 %
        MultipleCase{"cumulus_aircraft", 0.0, "particles", "balanced", 0.038, 1.0 / 3.0},  // 3.1 %, single 9.3 %
        // Seen against a low sun: the silver linings are the forward peak's orders (peak_orders.glsl).
        // Over the 10 % (design-notes.md); bounded here so that they stay.
        MultipleCase{"cumulus_field", 0.0, "particles", "exact", 0.2, 0.5},  // 15.9 %, single 37.6 %
        MultipleCase{"steam", 8.0, "particles", "balanced", 0.064, 0.0},  // 5.1 %
        MultipleCase{"steam", 8.0, "particles", "fast", 0.077, 0.0},  // 6.1 %
        MultipleCase{"smoke", 8.0, "particles", "balanced", 0.017, 0.0},  // 1.3 %
        MultipleCase{"smoke", 8.0, "particles", "fast", 0.027, 0.0},  // 2.2 %
        // A lamp inside the fire: its scattered light peaks within a voxel of it, which the grid smooths.
        MultipleCase{"campfire", 4.0, "particles", "balanced", 0.083, 0.0},  // 7.4 %
        MultipleCase{"jet", 6.0, "particles", "balanced", 0.032, 0.0},  // 2.5 %
        MultipleCase{"explosion", 0.8, "particles", "balanced", 0.048, 0.0},  // 3.8 %
        MultipleCase{"fog_smoke", 8.0, "particles", "balanced", 0.0062, 0.0}),  // 0.5 %
    [](const ::testing::TestParamInfo<MultipleCase>& param) {
        return std::string(param.param.scene) + "_" + param.param.mode + "_" + param.param.quality;
    });

}  // namespace
}  // namespace nimbus::test::media
