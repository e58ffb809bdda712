// `sheets` mode (image-aligned sheet-buffer splatting). Its point is the claim of the sheet-buffer
// splatting paper: no colour popping as the view turns. The camera orbits colour_pairs (pairs of
// dense, differently coloured particles side by side, whose depth order flips at 0 and ±0.95°) in
// steps of 0.25° and 0.125°; the largest frame-to-frame change of any pixel channel is measured in
// the sorted modes (billboards, particles: a flip swaps which colour lies in front) and in sheets.
// Sheets must change smoothly: its largest step at most a third of the sorted modes', and smaller
// with the smaller step. Then sheets against the reference on content and unseen scenes at 96×54
// (bounds 1.5 × the rel-RMSE measured when they were set, at least 0.003, at most the issue's
// 10%; particles' error printed beside it), every tier, and finite on every hard case.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <glm/gtc/matrix_transform.hpp>

#include "media_test_support.h"

namespace nimbus::test::media {
namespace {

constexpr int kOrbitWidth = 96, kOrbitHeight = 64;
constexpr double kOrbitSpan = 1.5;  // degrees each side of the file's camera: crosses all three flips

sandbox::SessionOptions inMode(const std::filesystem::path& scene, const std::string& mode, double time = 0.0,
                               const std::string& quality = "exact") {
    return {.scene = scene, .time = time, .settings = {"mode=" + mode, "quality=" + quality}, .scattering = assets::Scattering::Single};
}

double largestChange(const assets::RgbImage& a, const assets::RgbImage& b) {
    double largest = 0.0;
    for (std::size_t i = 0; i < a.rgb.size(); ++i) largest = std::max(largest, static_cast<double>(std::abs(a.rgb[i] - b.rgb[i])));
    return largest;
}

// The largest change of any pixel channel between consecutive frames as the camera orbits the
// y axis through the scene's target from −kOrbitSpan to +kOrbitSpan degrees in `step` degrees.
double largestOrbitStep(const std::string& mode, double step, const std::string& quality = "exact") {
    sandbox::Session session(inMode(mediaScene("colour_pairs"), mode, 0.0, quality));
    ecs::World& world = session.app().world();
    const ecs::Entity camera = nodeEntity(world, "main");
    const glm::dmat4 start = world.get<scene::Transform>(camera).world;  // the target is the origin (generate_media_scenes.py)
    assets::RgbImage previous;
    double largest = 0.0;
    const int steps = static_cast<int>(std::lround(2.0 * kOrbitSpan / step));
    for (int k = 0; k <= steps; ++k) {
        const double degrees = -kOrbitSpan + step * k;
        world.get<scene::Transform>(camera).world = glm::rotate(glm::dmat4(1.0), glm::radians(degrees), glm::dvec3(0.0, 1.0, 0.0)) * start;
        assets::RgbImage frame = session.renderRealtime(kOrbitWidth, kOrbitHeight);
        if (k > 0) largest = std::max(largest, largestChange(previous, frame));
        previous = std::move(frame);
    }
    return largest;
}

class SheetsPopping : public GlSceneTest {};

TEST_F(SheetsPopping, SheetsChangeSmoothlyWhereTheSortedModesPop) {
    const double billboards = largestOrbitStep("billboards", 0.25), particles = largestOrbitStep("particles", 0.25);
    const double particlesFine = largestOrbitStep("particles", 0.125);
    std::printf("[ measured ] largest step: billboards %.4f, particles %.4f (0.125 deg: %.4f)\n", billboards, particles, particlesFine);
    // The sorted modes' pop is the flip itself: it does not shrink with the step.
    EXPECT_GT(particlesFine, 0.75 * particles);
    for (const char* tier : {"exact", "balanced", "fast"}) {
        const double sheets = largestOrbitStep("sheets", 0.25, tier), sheetsFine = largestOrbitStep("sheets", 0.125, tier);
        std::printf("[ measured ] largest step: sheets quality=%s %.4f (0.125 deg: %.4f)\n", tier, sheets, sheetsFine);
        EXPECT_GT(sheets, 0.0) << tier << ": the orbit moved nothing";
        EXPECT_LE(sheets, billboards / 3.0) << tier;
        EXPECT_LE(sheets, particles / 3.0) << tier;
        EXPECT_LT(sheetsFine, 0.75 * sheets) << tier << ": a smooth change halves with the step";
    }
}

struct SheetsCase {
    const char* scene;
    bool content;  // content/scenes, else tests/data/media_scenes
    double time;
    double measured;  // when the bound was set (documentation only)
    double bound;
};

void PrintTo(const SheetsCase& c, std::ostream* os) { *os << c.scene << " at t=" << c.time << " s"; }

class SheetsVsReference : public GlSceneTest, public ::testing::WithParamInterface<SheetsCase> {};

constexpr int kWidth = 96, kHeight = 54;

TEST_P(SheetsVsReference, RelRmseWithinTheScenesBound) {
    const SheetsCase& c = GetParam();
    const std::filesystem::path scene = c.content ? contentScene(c.scene) : mediaScene(c.scene);
    sandbox::Session session(inMode(scene, "sheets", c.time));
    const assets::RgbImage reference = renderReference(session, kWidth, kHeight);
    const auto metrics = nimbus::media::reference::compareImages(session.renderRealtime(kWidth, kHeight), reference);
    EXPECT_EQ(metrics.nonfinite, 0u);
    EXPECT_LE(metrics.relRmse, c.bound) << "measured " << c.measured << " when the bound was set";
    // `particles` beside it, for the record (the same state: both modes simulate the same steps).
    sandbox::Session particles(inMode(scene, "particles", c.time));
    const double particlesError = nimbus::media::reference::compareImages(particles.renderRealtime(kWidth, kHeight), reference).relRmse;
    std::printf("[ measured ] sheets %s t=%.2f rel_rmse=%.4f (bound %.3f; particles %.4f)\n", c.scene, c.time, metrics.relRmse, c.bound,
                particlesError);
}

INSTANTIATE_TEST_SUITE_P(
    Scenes, SheetsVsReference,
    ::testing::Values(SheetsCase{"smoke", true, 8.0, 0.0122, 0.019}, SheetsCase{"cloud", true, 0.0, 0.0145, 0.022},
                      SheetsCase{"campfire", true, 4.0, 0.0092, 0.014}, SheetsCase{"jet", true, 6.0, 0.0052, 0.008},
                      SheetsCase{"explosion", true, 0.8, 0.0057, 0.009}, SheetsCase{"cumulus", true, 0.0, 0.0006, 0.003},
                      SheetsCase{"cumulus_aircraft", true, 0.0, 0.0012, 0.003}, SheetsCase{"fog_smoke", true, 8.0, 0.0032, 0.005},
                      SheetsCase{"colour_pairs", false, 0.0, 0.0032, 0.005}, SheetsCase{"unseen_albedo_mix", false, 0.0, 0.0004, 0.003},
                      // A plate through a thick cloud: the sheets stop at the mesh's depth per pixel.
                      SheetsCase{"unseen_mesh_through_medium", false, 0.0, 0.0120, 0.019},
                      SheetsCase{"unseen_camera_inside", false, 0.0, 0.0073, 0.011}, SheetsCase{"unseen_point_inside", false, 0.0, 0.0089, 0.014},
                      SheetsCase{"unseen_thick_cumulus", false, 0.0, 0.0008, 0.003}, SheetsCase{"unseen_radius_mix", false, 0.0, 0.0001, 0.003},
                      SheetsCase{"unseen_far_from_origin", false, 0.0, 0.0004, 0.003}, SheetsCase{"unseen_forward_glow", false, 0.0, 0.0024, 0.004}),
    [](const ::testing::TestParamInfo<SheetsCase>& param) { return std::string(param.param.scene); });

// Every tier draws (the tiers change the spacing and the lighting) and stays near the reference.
class SheetsTiers : public GlSceneTest {};

TEST_F(SheetsTiers, EveryTierDrawsItsOwnFrameNearTheReference) {
    std::vector<assets::RgbImage> frames;
    for (const char* tier : {"exact", "balanced", "fast"}) {
        sandbox::Session session(inMode(contentScene("smoke"), "sheets", 8.0, tier));
        frames.push_back(session.renderRealtime(kWidth, kHeight));
        const auto metrics = nimbus::media::reference::compareImages(frames.back(), renderReference(session, kWidth, kHeight));
        std::printf("[ measured ] sheets smoke quality=%s rel_rmse=%.4f\n", tier, metrics.relRmse);
        EXPECT_LE(metrics.relRmse, 0.10) << tier;
    }
    EXPECT_GT(largestChange(frames[0], frames[1]), 0.0) << "balanced draws what exact draws";
    EXPECT_GT(largestChange(frames[1], frames[2]), 0.0) << "fast draws what balanced draws";
}

// Every hard case of tests/data/stability_scenes renders finite and without GL errors.
class SheetsHardCases : public GlSceneTest {};

TEST_F(SheetsHardCases, EveryHardCaseStaysFinite) {
    int scenes = 0;
    for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(NIMBUS_TEST_DATA_DIR) / "stability_scenes")) {
        if (entry.path().extension() != ".gltf") continue;
        SCOPED_TRACE(entry.path().filename().string());
        sandbox::Session session(inMode(entry.path(), "sheets"));
        const assets::RgbImage image = session.renderRealtime(64, 36);
        EXPECT_EQ(countNonfinite(image), 0u);
        EXPECT_EQ(context().takeGlErrors().count, 0u);
        ++scenes;
    }
    EXPECT_GE(scenes, 15);
}

}  // namespace
}  // namespace nimbus::test::media
