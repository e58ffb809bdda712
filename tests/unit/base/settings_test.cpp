// Tests engine/base/src/settings.cpp: explicit values, scene defaults and presets, and where each
// value says it came from.
#include "nimbus/base/settings.h"

#include <gtest/gtest.h>

#include "nimbus/base/error.h"

namespace nimbus {
namespace {

Settings withQualityPresets() {
    Settings s;
    s.declare("quality", "");
    s.declare("slices", "");
    s.declare("media_scale", "");
    s.definePreset("quality", "fast", {{"slices", "16"}, {"media_scale", "0.5"}});
    s.definePreset("quality", "exact", {});
    return s;
}

TEST(SettingsPreset, SuppliesWhatNothingSet) {
    Settings s = withQualityPresets();
    EXPECT_FALSE(s.integer("slices", 4, 32).has_value());  // no quality chosen: no preset
    s.set("quality", "fast", "--quality");
    EXPECT_EQ(s.integer("slices", 4, 32), 16);
    EXPECT_EQ(s.origin("slices"), "quality=fast (from --quality)");
    EXPECT_FALSE(s.has("slices"));  // a preset's value is not a set one
}

TEST(SettingsPreset, ExplicitValuesWin) {
    Settings s = withQualityPresets();
    s.set("quality", "fast");
    s.set("slices", "8", "--set");
    EXPECT_EQ(s.integer("slices", 4, 32), 8);
    EXPECT_EQ(s.number("media_scale", 0.0, 1.0), 0.5);
}

TEST(SettingsPreset, SwitchingTheQualitySwitchesEverythingItPicked) {
    Settings s = withQualityPresets();
    s.set("quality", "fast");
    ASSERT_TRUE(s.number("media_scale", 0.0, 1.0).has_value());
    s.set("quality", "exact");
    EXPECT_FALSE(s.number("media_scale", 0.0, 1.0).has_value());
    EXPECT_EQ(s.presetValues("quality"), (std::vector<std::string>{"fast", "exact"}));
}

TEST(SettingsPreset, APresetValueOutOfRangeNamesThePreset) {
    Settings s = withQualityPresets();
    s.set("quality", "fast", "scene.gltf: render.quality");
    try {
        (void)s.integer("slices", 20, 32);
        FAIL() << "expected an InputError";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("quality=fast (from scene.gltf: render.quality)"), std::string::npos) << e.what();
    }
}

TEST(SettingsPreset, SceneDefaultsYieldToTheCommandLine) {
    Settings s = withQualityPresets();
    s.set("quality", "exact", "--quality");
    s.setDefault("quality", "fast", "scene.gltf: render.quality");
    EXPECT_EQ(s.text("quality"), "exact");
    EXPECT_EQ(s.origin("quality"), "--quality");
}

}  // namespace
}  // namespace nimbus
