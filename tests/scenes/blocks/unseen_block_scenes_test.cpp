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
#include <map>
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

// With $NIMBUS_BLOCK_SCENES_DUMP set, the seam test writes there what it compared
// (<scene>_{reference,blocks,smooth,billboards,band}.exr; blocks is the default, seam; the band is 1
// inside it), to see where an error lies.
void dump(const std::string& scene, const char* what, const assets::RgbImage& image) {
    const char* folder = std::getenv("NIMBUS_BLOCK_SCENES_DUMP");
    if (folder == nullptr || *folder == '\0') return;
    std::filesystem::create_directories(folder);
    assets::writeImage(std::filesystem::path(folder) / (scene + "_" + what + ".exr"), image);
}

assets::RgbImage bandMask(const std::vector<std::size_t>& band, int width, int height) {
    assets::RgbImage mask(width, height);
    for (const std::size_t k : band)
        mask.set(static_cast<int>(k % static_cast<std::size_t>(width)), static_cast<int>(k / static_cast<std::size_t>(width)), glm::vec3(1.0f));
    return mask;
}
constexpr int kWidth = 256, kHeight = 144;
constexpr double kMaxRelRmse = 0.08;

// Measured rel_rmse at 256×144 (blocks / particles); 01, 04 and 07 have a point light:
//   00 blob   τ 0.6  wing        1.75% / 1.75%      05 blob   τ 4.0  plate       0.49% / 0.44%
//   01 blob          wing+lamp   1.95% / 1.84%      06 layer  τ 1.5  wing        1.33% / 1.33%
//   02 twin   τ 3.0  plate       0.56% / 0.55%      07 cigar         plate+lamp  1.08% / 0.65%
//   03 tower  τ 1.0  wing        0.94% / 0.93%      08 tower  τ 5.5  plate       0.33% / 0.37%
//   04 cigar         plate+lamp  1.44% / 1.26%      09 cigar  τ 2.2  wing        1.64% / 1.64%
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

// The other tiers on the same scenes and reference: blocks and particles in balanced within the
// unseen bounds (8 %, 10 %), particles in fast within the fast tier's unseen bound (15 %,
// unseen_scenes_test.cpp).
TEST_P(UnseenBlockScenesTest, BlocksStayWithinEightPercentOfTheReference) {
    const std::filesystem::path scene = sceneDir() / (GetParam() + ".gltf");
    const assets::RgbImage reference = renderReference(scene, kWidth, kHeight);
    const assets::RgbImage blocks = renderRealtime(scene, kWidth, kHeight, {"mode=blocks"});
    const assets::RgbImage particles = renderRealtime(scene, kWidth, kHeight, {});
    const double error = relRmse(blocks, reference), particlesError = relRmse(particles, reference);
    RecordProperty("blocks_rel_rmse", std::to_string(error));
    RecordProperty("particles_rel_rmse", std::to_string(particlesError));
    EXPECT_EQ(media::reference::compareImages(blocks, reference).nonfinite, 0u);
    EXPECT_LE(error, kMaxRelRmse);
    const struct {
        const char* name;
        std::vector<std::string> settings;
        double bound;
    } tiers[] = {{"blocks balanced", {"mode=blocks", "quality=balanced"}, kMaxRelRmse},
                 {"particles balanced", {"quality=balanced"}, 0.10},
                 {"particles fast", {"quality=fast"}, 0.15}};
    std::string line;
    for (const auto& tier : tiers) {
        const assets::RgbImage image = renderRealtime(scene, kWidth, kHeight, tier.settings);
        const double tierError = relRmse(image, reference);
        EXPECT_EQ(media::reference::compareImages(image, reference).nonfinite, 0u) << tier.name;
        EXPECT_LE(tierError, tier.bound) << tier.name;
        line += std::string(", ") + tier.name + " " + std::to_string(tierError).substr(0, 6);
    }
    std::printf("%s: blocks %.4f, particles %.4f%s\n", GetParam().c_str(), error, particlesError, line.c_str());
}

// The seam criterion of cloud_blocks_test.cpp: in the band of pixels where the wing lies inside
// the cloud, blocks err less than billboards without soft particles. Seam band rel_rmse, blocks
// (the automatic count: 2√N, 48 for 04) vs particles with soft_particles=off:
//   00 0.32% vs 1.11%, 01 2.43% vs 3.07%, 02 3.77% vs 4.14%, 03 0.41% vs 0.87%, 04 9.39% vs 37.9%,
//   05 1.59% vs 2.33%, 06 0.68% vs 0.93%, 07 3.49% vs 4.13%, 08 2.80% vs 3.03%, 09 1.23% vs 3.41%
// History: only 00 passed while a block was cut at the surface uniformly over [front, back] and
// shaded at one point. With a depth profile from the impostor's moments, silhouettes cut at the
// particles and a texel per pixel for small particles, 01 still failed (4.12% vs 4.03%): the
// two-moment profile misplaced the cut by up to a particle. The cut is now exact from the block's
// own particles where the surface lies among them (block_composite.frag listedMassBefore), and 01
// passed (3.82% vs 4.03%) until slices resolved dense particles (slice_plan.cpp), which helped
// billboards there more than blocks. Then particles mode's light stopped being taken at one point
// of each dense particle (lighting.glsl layerLightTransmittance), and billboards' band error fell
// by a third to a half, below blocks' on 01, 05, 07 and 08. Blocks' two shading pieces had equal
// weights whatever the depth profile held in each; weighted by the profile's mass
// (block_lighting.glsl blockSegmentSource) the band error fell on nine of ten (01 3.93% → 2.70%,
// 05 3.36% → 1.66%, 07 6.83% → 3.84%, 08 4.40% → 3.49%; cloud.gltf 1.18% → 0.76%); counting the
// kernels' tails past [front, back] took 08 to 3.20%, and the mass in front of a cut read from the
// block's own particles (its wing shadows the cloud in front of its dark face) to 2.80%.
// Generated scenes, not committed (make_block_scenes.py with BASE_SEED 9100 to 9500): 47 of 50
// pass. Two σ 11–14 clouds that failed pass since the automatic count bounds a block's optical
// thickness (block_partition.h); 9300/07 (7.24% → 3.93%) and the lamp scenes here (01 2.60% →
// 2.43%, 07 3.83% → 3.49%) improved when lamp views stopped losing particles beside the lamp
// (block_impostors.vert). Failing, all with a lamp: 9200/07 (4.41% vs 3.57%: a block's own
// shadow, median thickness 0.49, just under the bound), 9300/07 (3.93% vs 3.57%: both modes dark
// at the lamp, blocks more) and 9300/01 (2.12% vs 2.02%). All 50 pass since (block_partition.h).
// On all 90 of seeds 9100-9900, after a lamp's slices took the blocks it sees wide particle by
// particle: every scene within 2.8% overall, and 84 pass the band. block_scene_9700_07 (kept from
// seed 9700) went 8.42% → 1.63% (billboards 2.35%). Failing: 9600/08 3.53/2.21, 9700/04 1.28/1.15,
// 9700/08 1.41/1.19, 9800/01 3.10/2.23, 9900/01 3.42/3.30, 9900/09 2.65/2.23; 9800/01 errs in
// sunlight without the wing or the lamp, where blocks of small dense particles are shaded at their
// pieces' uniform points (shaded from their own particles, 9800/01 and 9900/01 pass).
// block_shading=seam shades blocks exactly (from their own particles, with the compositing order of
// overlapping blocks corrected) near the texels where the mesh lies among their particles
// (block_seam_mask_pass.cpp), and smoothly elsewhere. Its band is block_shading=exact's to the bit
// (cloud_blocks_test.cpp SeamShadingIsExactAtTheSeam...), and it passes every scene tried: the 13
// that smooth failed among seeds 9100-10300 (9600/08 1.43% vs 2.21%, 9700/04 0.73/1.15, 9700/08
// 0.33/1.19, 9800/01 1.45/2.23, 9900/01 2.05/3.30, 9900/09 1.63/2.23, 10000/08 0.78/1.13, 10100/02
// 1.96/2.12, 10100/04 1.48/2.78, 10100/05 1.04/1.65, 10200/07 0.74/1.93, 10300/02 1.07/1.34,
// 10300/07 1.86/2.78) and all 20 of fresh seeds 10400 and 10500, where smooth failed 10400/07 (6.38%
// vs 2.85%; seam 2.25%). On all 150 scenes of seeds 9100-10500 (2026-12-02), seam passes 150 (whole
// image at most 3.15%) and smooth fails 16, so seam is the default; smooth, the faster setting, is
// asserted too, except where it is known to fail.
const std::map<std::string, std::string> kSmoothSeamKnownFailing = {
    {"block_scene_9700_08", "overlapping blocks' compositing order: 1.41% / billboards 1.19%"},
    {"block_scene_9800_01", "small dense particles shaded at uniform points: 3.10% / billboards 2.23%"},
};

class UnseenSeamBandTest : public GlSceneTest, public ::testing::WithParamInterface<std::string> {};

TEST_P(UnseenSeamBandTest, SeamBandErrorIsBelowParticlesWithoutSoftParticles) {
    const std::filesystem::path scene = sceneDir() / (GetParam() + ".gltf");
    const assets::RgbImage reference = renderReference(scene, kWidth, kHeight);
    std::size_t seamPixels = 0;
    const std::vector<std::size_t> band = seamBand(scene, kWidth, kHeight, "wing", 2, &seamPixels);
    ASSERT_GT(seamPixels, 100u) << "the thin mesh must cut the cloud in this view";
    const assets::RgbImage seamImage = renderRealtime(scene, kWidth, kHeight, {"mode=blocks"});  // block_shading=seam
    const assets::RgbImage smoothImage = renderRealtime(scene, kWidth, kHeight, {"mode=blocks", "block_shading=smooth"});
    const assets::RgbImage billboardsImage = renderRealtime(scene, kWidth, kHeight, {"soft_particles=off"});
    const double smooth = relRmseOver(smoothImage, reference, band);
    const double seam = relRmseOver(seamImage, reference, band);
    const double billboards = relRmseOver(billboardsImage, reference, band);
    const double seamWhole = relRmse(seamImage, reference);
    dump(GetParam(), "reference", reference);
    dump(GetParam(), "blocks", seamImage);
    dump(GetParam(), "smooth", smoothImage);
    dump(GetParam(), "billboards", billboardsImage);
    dump(GetParam(), "band", bandMask(band, kWidth, kHeight));
    std::printf("%s: seam band (%zu px) blocks %.4f, block_shading=smooth %.4f, particles soft_particles=off %.4f; blocks whole image %.4f\n",
                GetParam().c_str(), band.size(), seam, smooth, billboards, seamWhole);
    RecordProperty("seam_band_blocks", std::to_string(seam));
    RecordProperty("seam_band_smooth_blocks", std::to_string(smooth));
    RecordProperty("seam_band_billboards", std::to_string(billboards));
    EXPECT_LT(seam, billboards) << "blocks (block_shading=seam, the default)";
    EXPECT_LE(seamWhole, kMaxRelRmse) << "blocks (block_shading=seam, the default)";
    if (kSmoothSeamKnownFailing.count(GetParam()) == 0) {
        EXPECT_LT(smooth, billboards) << "block_shading=smooth";
    }
    else std::printf("  block_shading=smooth not asserted (%s)\n", kSmoothSeamKnownFailing.at(GetParam()).c_str());
}

std::string sceneName(const ::testing::TestParamInfo<std::string>& scene) { return scene.param; }

INSTANTIATE_TEST_SUITE_P(Generated, UnseenBlockScenesTest, ::testing::ValuesIn(sceneNames()), sceneName);
INSTANTIATE_TEST_SUITE_P(Generated, UnseenSeamBandTest, ::testing::ValuesIn(sceneNames()), sceneName);
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(UnseenBlockScenesTest);  // an empty folder fails AreThere instead
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(UnseenSeamBandTest);

TEST(UnseenBlockScenes, AreThere) { EXPECT_GE(sceneNames().size(), 8u) << "no scenes in " << sceneDir(); }

}  // namespace
}  // namespace nimbus::test
