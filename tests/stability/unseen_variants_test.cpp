// "Scenes we have not seen, with the same kinds of hard cases, stay finite and within 15%": every
// scene in tests/data/stability_scenes/unseen/ (seeded random combinations of the hard cases'
// parameters, written by generate_stability_scenes.py: optical depth 1e-5 … 1e4, sub-pixel to
// screen-sized particles, light along / against / across the view or a spot inside the cloud,
// g = −0.99 … 0.99, 1 to 2000 particles, 1e5 m from the origin, the camera inside, the ground
// through the particle centres), or every scene in $NIMBUS_STABILITY_SCENES when that is set
// (at test discovery: run the executable directly to check other variants, e.g.
// `generate_stability_scenes.py --unseen /tmp/v --seed 7` then
// `NIMBUS_STABILITY_SCENES=/tmp/v nimbus_stability_unseen_tests`).
//
// Each is rendered at 160×90 through its first camera at t = 0 and gets the hard cases' assertions
// (stability_harness.h): finite everywhere, no GL error, the reference converged, and both modes
// within 15% rel-RMSE of the reference.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "stability_harness.h"

namespace nimbus::stability {
namespace {

std::vector<std::string> variantScenes() {
    const char* override = std::getenv("NIMBUS_STABILITY_SCENES");
    const std::filesystem::path folder = override != nullptr && *override != '\0' ? std::filesystem::path(override)
                                                                                 : sceneDirectory() / "unseen";
    std::vector<std::string> scenes;
    if (!std::filesystem::is_directory(folder)) return scenes;
    for (const auto& entry : std::filesystem::directory_iterator(folder)) {
        const std::string ext = entry.path().extension().string();
        if (ext == ".gltf" || ext == ".glb") scenes.push_back(std::filesystem::absolute(entry.path()).string());
    }
    std::sort(scenes.begin(), scenes.end());
    return scenes;
}

std::string testName(const ::testing::TestParamInfo<std::string>& info) {
    std::string name = std::filesystem::path(info.param).stem().string();
    for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    return name;
}

class UnseenVariantTest : public StabilityTest, public ::testing::WithParamInterface<std::string> {
protected:
    HardCase variant() const { return {.name = testName({GetParam(), 0}), .scene = GetParam()}; }
};

TEST_P(UnseenVariantTest, StaysFinite) {
    const HardCase c = variant();
    expectFiniteAndClean(c, runCase(context(), c));
}

TEST_P(UnseenVariantTest, WithinBound) {
    const HardCase c = variant();
    const CaseRun& run = runCase(context(), c);
    expectWithinBound(c, run, media::MediaMode::Particles, kDefaultErrorBound);
    expectWithinBound(c, run, media::MediaMode::Blocks, kDefaultErrorBound);
}

TEST(UnseenVariants, AreThere) { EXPECT_GE(variantScenes().size(), 6u) << "no variant scenes found"; }

INSTANTIATE_TEST_SUITE_P(Generated, UnseenVariantTest, ::testing::ValuesIn(variantScenes()), testName);

}  // namespace
}  // namespace nimbus::stability
