// Tests media::idleSettings (core/src/common/media_settings.cpp): the keys a user set that would
// not act on the frame, named with why, from the declarations alone.
#include <gtest/gtest.h>

#include <string>

#include "nimbus/base/settings.h"
#include "nimbus/media/media_settings.h"
#include "nimbus/media/technique.h"

namespace nimbus::media {
namespace {

std::vector<IdleSetting> idleWith(const std::vector<std::string>& assignments, bool multiple = true) {
    const TechniqueTable table = builtInTechniques();
    Settings settings;
    declareMediaSettings(settings, table);
    for (const std::string& a : assignments) settings.assign(a);
    return idleSettings(settings, table, multiple);
}

TEST(IdleSettings, AKeyOfAnotherModeHasNoEffect) {
    const auto idle = idleWith({"mode=billboards", "slices=8", "blocks=10", "media_scale=0.5"});
    ASSERT_EQ(idle.size(), 2u);
    EXPECT_EQ(idle[0].key, "slices");
    EXPECT_NE(idle[0].why.find("mode billboards"), std::string::npos) << idle[0].why;
    EXPECT_EQ(idle[1].key, "blocks");
}

TEST(IdleSettings, AKeyAnotherKeyTurnsOffHasNoEffect) {
    EXPECT_TRUE(idleWith({"quality=exact", "soft_particles=off"}).empty());
    const auto balanced = idleWith({"quality=balanced", "soft_particles=off"});
    ASSERT_EQ(balanced.size(), 1u);
    EXPECT_NE(balanced[0].why.find("tier balanced"), std::string::npos) << balanced[0].why;
    EXPECT_NE(balanced[0].why.find("lighting=fragment"), std::string::npos) << balanced[0].why;
    // Setting what turns it on makes it act in any tier.
    EXPECT_TRUE(idleWith({"quality=balanced", "lighting=fragment", "soft_particles=off"}).empty());
    EXPECT_EQ(idleWith({"quality=exact", "slice_detail=2"}).size(), 1u);
    EXPECT_TRUE(idleWith({"quality=exact", "slice_resolution=auto", "slice_detail=2"}).empty());
    EXPECT_EQ(idleWith({"upsample_threshold=0.5"}).size(), 1u);
    EXPECT_TRUE(idleWith({"media_scale=0.5", "upsample_threshold=0.5"}).empty());
}

TEST(IdleSettings, MultipleScatteringKeysHaveNoEffectInTheSingleModel) {
    EXPECT_TRUE(idleWith({"scattering_voxels=16"}, true).empty());
    const auto single = idleWith({"scattering_voxels=16"}, false);
    ASSERT_EQ(single.size(), 1u);
    EXPECT_NE(single[0].why.find("single-scattering"), std::string::npos) << single[0].why;
}

}  // namespace
}  // namespace nimbus::media
