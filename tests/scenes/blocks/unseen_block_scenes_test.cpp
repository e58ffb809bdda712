// Blocks mode on scenes its author never tuned for: tests/data/block_scenes/, written by the seeded
// make_block_scenes.py there (clouds of five shapes, thin to moderately thick, small to large
// particles, a thin "wing" or plate through the cloud at a random angle, random sun, sometimes a
// point light). Each must stay within the 8% rel-RMSE of the reference; the particles
// mode's error is printed and recorded beside it. Every scene in the folder is judged, or every
// scene in $NIMBUS_BLOCK_SCENES when that is set (the list is made at test discovery, so run the
// executable directly to judge scenes from another seed:
//   sed 's/^BASE_SEED = .*/BASE_SEED = 9100/' make_block_scenes.py, written to another folder, then
//   NIMBUS_BLOCK_SCENES=/tmp/s9100 build/<dir>/bin/nimbus_blocks_scene_tests --gtest_filter='*Unseen*').
#include <algorithm>
#include <cstdlib>
#include <string>
#include <vector>

#include "../render_fixture.h"
#include "blocks_scene_fixture.h"

namespace nimbus::test {
namespace {

std::filesystem::path sceneDir() {
    const char* override = std::getenv("NIMBUS_BLOCK_SCENES");
    if (override != nullptr && *override != '\0') return override;
    return std::filesystem::path(NIMBUS_TEST_DATA_DIR) / "block_scenes";
}
constexpr int kWidth = 256, kHeight = 144;
constexpr double kMaxRelRmse = 0.08;

// Measured rel_rmse at 256×144 (blocks / particles); 01, 04 and 07 have a point light:
//   00 blob   τ 0.6  wing        1.76% / 1.76%      05 blob   τ 4.0  plate       0.97% / 1.11%
//   01 blob          wing+lamp   2.53% / 1.92%      06 layer  τ 1.5  wing        1.34% / 1.33%
//   02 twin   τ 3.0  plate       0.63% / 0.63%      07 cigar         plate+lamp  1.86% / 2.52%
//   03 tower  τ 1.0  wing        0.95% / 0.94%      08 tower  τ 5.5  plate       0.59% / 0.92%
//   04 cigar         plate+lamp  1.90% / 2.27%      09 cigar  τ 2.2  wing        1.65% / 1.66%
// The lamps' scenes were 26.5%, 14.3% and 27.4% in blocks while a block was lit at one point per
// pixel; its light is now integrated over each block's segment with the density of the block's
// own particles near the lamp (block_lighting.glsl). 04 was also 11% in both modes: its lamp
// sits 3 cm under the plate, and a mesh shadow softened over R/3 let it light the medium above.
std::vector<std::string> sceneNames() {
    std::vector<std::string> names;
    if (!std::filesystem::is_directory(sceneDir())) return names;
    for (const auto& entry : std::filesystem::directory_iterator(sceneDir()))
        if (entry.path().extension() == ".gltf") names.push_back(entry.path().stem().string());
    std::sort(names.begin(), names.end());
    return names;
}

class UnseenBlockScenesTest : public GlSceneTest, public ::testing::WithParamInterface<std::string> {};

TEST_P(UnseenBlockScenesTest, BlocksStayWithinEightPercentOfTheReference) {
    const std::filesystem::path scene = sceneDir() / (GetParam() + ".gltf");
    const assets::RgbImage reference = renderReference(scene, kWidth, kHeight);
    const assets::RgbImage blocks = renderRealtime(scene, kWidth, kHeight, {"mode=blocks"});
    const assets::RgbImage particles = renderRealtime(scene, kWidth, kHeight, {});
    const double error = relRmse(blocks, reference), particlesError = relRmse(particles, reference);
    RecordProperty("blocks_rel_rmse", std::to_string(error));
    RecordProperty("particles_rel_rmse", std::to_string(particlesError));
    std::printf("%s: blocks %.4f, particles %.4f\n", GetParam().c_str(), error, particlesError);
    EXPECT_EQ(media::reference::compareImages(blocks, reference).nonfinite, 0u);
    EXPECT_LE(error, kMaxRelRmse);
}

// The seam criterion of cloud_blocks_test.cpp: in the band of pixels where the wing lies inside
// the cloud, blocks err less than billboards without soft particles. Seam band rel_rmse, blocks
// (2√N blocks) vs particles with soft_particles=off:
//   00 0.66% vs 1.26%, 01 4.12% vs 4.19%, 02 4.39% vs 4.92%, 03 0.70% vs 0.93%, 04 10.9% vs 38.9%,
//   05 3.59% vs 3.98%, 06 1.04% vs 1.13%, 07 6.90% vs 8.67%, 08 4.91% vs 7.27%, 09 1.86% vs 4.19%
// 01 and 06 failed (4.31%, 1.14%) until impostors cut optical depth at the particles' silhouette
// and gave small particles a texel per pixel (impostor_atlas.h). Only 00 passed while a block was
// cut at the surface uniformly over [front, back] and shaded at one point (block_lighting.glsl
// BlockProfile, BLOCK_SHADING_PIECES). The margins on 01 and 06 are small, and the criterion is
// not met everywhere: on scenes from the generator's seeds 9100 and 9200 (not committed) it held
// on 16 of 20 (failing 9100/02 3.13% vs 2.79%, 9100/04 7.7% vs 6.1%, 9100/05 2.46% vs 1.66%,
// 9200/04 11.7% vs 10.5%).
class UnseenSeamBandTest : public GlSceneTest, public ::testing::WithParamInterface<std::string> {};

TEST_P(UnseenSeamBandTest, SeamBandErrorIsBelowParticlesWithoutSoftParticles) {
    const std::filesystem::path scene = sceneDir() / (GetParam() + ".gltf");
    const assets::RgbImage reference = renderReference(scene, kWidth, kHeight);
    std::size_t seamPixels = 0;
    const std::vector<std::size_t> band = seamBand(scene, kWidth, kHeight, "wing", 2, &seamPixels);
    ASSERT_GT(seamPixels, 100u) << "the thin mesh must cut the cloud in this view";
    const double blocks = relRmseOver(renderRealtime(scene, kWidth, kHeight, {"mode=blocks"}), reference, band);
    const double billboards = relRmseOver(renderRealtime(scene, kWidth, kHeight, {"soft_particles=off"}), reference, band);
    std::printf("%s: seam band (%zu px) blocks %.4f, particles soft_particles=off %.4f\n", GetParam().c_str(), band.size(), blocks, billboards);
    EXPECT_LT(blocks, billboards);
}

std::string sceneName(const ::testing::TestParamInfo<std::string>& scene) { return scene.param; }

INSTANTIATE_TEST_SUITE_P(Generated, UnseenBlockScenesTest, ::testing::ValuesIn(sceneNames()), sceneName);
INSTANTIATE_TEST_SUITE_P(Generated, UnseenSeamBandTest, ::testing::ValuesIn(sceneNames()), sceneName);
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(UnseenBlockScenesTest);  // an empty folder fails AreThere instead
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(UnseenSeamBandTest);

TEST(UnseenBlockScenes, AreThere) { EXPECT_GE(sceneNames().size(), 8u) << "no scenes in " << sceneDir(); }

}  // namespace
}  // namespace nimbus::test
