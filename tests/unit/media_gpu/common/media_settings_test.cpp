// Tests core/src/common/media_settings.cpp's tier defaults: a technique's own defaults for shared
// keys (TechniqueEntry::sharedDefaults) apply in its mode and tier only, and a key set explicitly wins.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "nimbus/base/settings.h"
#include "nimbus/media/media_settings.h"
#include "nimbus/media/technique.h"

namespace nimbus::media {
namespace {

MediaRenderSettings readWith(const std::vector<std::string>& assignments) {
    const TechniqueTable table = builtInTechniques();
    Settings settings;
    declareMediaSettings(settings, table);
    for (const std::string& a : assignments) settings.assign(a);
    return readMediaSettings(settings, table);
}

// Blocks in fast and particles in balanced take finer slices where a mesh reaches into the medium;
// no other mode or tier does.
TEST(MediaSettings, BlocksInFastTakeFinerSlicesNearMeshes) {
    const MediaRenderSettings blocks = readWith({"mode=blocks", "quality=fast"});
    EXPECT_EQ(blocks.slices, 16);
    EXPECT_FLOAT_EQ(blocks.sliceTexelsPerRadius, 2.0f);
    EXPECT_EQ(blocks.slicesNearMeshes, 32);
    EXPECT_FLOAT_EQ(blocks.sliceTexelsPerRadiusNearMeshes, 4.0f);
    const MediaRenderSettings tierOnly = mediaSettingsForTier(QualityTier::Fast, builtInTechniques(), "blocks");
    EXPECT_EQ(tierOnly.slicesNearMeshes, 32) << "a host that takes the tier's settings gets the same";
    const MediaRenderSettings balanced = readWith({"mode=particles", "quality=balanced"});
    EXPECT_FLOAT_EQ(balanced.sliceTexelsPerRadius, 4.0f);
    EXPECT_FLOAT_EQ(balanced.sliceTexelsPerRadiusNearMeshes, 6.0f);
    EXPECT_EQ(balanced.slicesNearMeshes, 0);
    for (const auto& other : {std::vector<std::string>{"mode=particles", "quality=fast"}, {"mode=raymarch", "quality=fast"},
                              {"mode=blocks", "quality=balanced"}, {"mode=blocks", "quality=exact"}, {"mode=particles", "quality=exact"}}) {
        const MediaRenderSettings s = readWith(other);
        EXPECT_EQ(s.slicesNearMeshes, 0) << other[0] << " " << other[1];
        EXPECT_EQ(s.sliceTexelsPerRadiusNearMeshes, 0.0f) << other[0] << " " << other[1];
    }
}

TEST(MediaSettings, AKeySetExplicitlyWinsNearMeshesToo) {
    const MediaRenderSettings slices = readWith({"mode=blocks", "quality=fast", "slices=8"});
    EXPECT_EQ(slices.slices, 8);
    EXPECT_EQ(slices.slicesNearMeshes, 0);
    EXPECT_FLOAT_EQ(slices.sliceTexelsPerRadiusNearMeshes, 4.0f);
    const MediaRenderSettings detail = readWith({"mode=blocks", "quality=fast", "slice_detail=3"});
    EXPECT_EQ(detail.slicesNearMeshes, 32);
    EXPECT_EQ(detail.sliceTexelsPerRadiusNearMeshes, 0.0f);
    const MediaRenderSettings fixed = readWith({"mode=blocks", "quality=fast", "slice_resolution=64"});
    EXPECT_EQ(fixed.sliceTexelsPerRadius, 0.0f);
    EXPECT_EQ(fixed.sliceTexelsPerRadiusNearMeshes, 0.0f);
    // auto is fast's own resolution: the detail near meshes stays.
    EXPECT_FLOAT_EQ(readWith({"mode=blocks", "quality=fast", "slice_resolution=auto"}).sliceTexelsPerRadiusNearMeshes, 4.0f);
}

// Starting a changed frame's grid solve from the last frame's answer is a host's choice: no tier
// takes it (a frame's picture then depends on the frames before it), and a key set explicitly wins.
TEST(MediaSettings, WarmStartingTheScatteringGridIsOptIn) {
    for (const char* tier : {"quality=fast", "quality=balanced", "quality=exact"}) EXPECT_EQ(readWith({tier}).scatteringWarmSweeps, 0) << tier;
    EXPECT_EQ(readWith({"mode=blocks", "quality=fast"}).scatteringWarmSweeps, 0);
    EXPECT_EQ(readWith({"quality=fast", "scattering_warm_sweeps=16"}).scatteringWarmSweeps, 16);
}

}  // namespace
}  // namespace nimbus::media
