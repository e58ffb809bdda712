// Tests engine/base/src/settings.cpp: keys declared once with their specs, values checked against
// them with messages that name where a value came from, scene defaults that yield to the command
// line, and typed settings read on top of a tier's.
#include "nimbus/base/settings.h"

#include <gtest/gtest.h>

#include "nimbus/base/error.h"
#include "nimbus/base/quality_tier.h"

namespace nimbus {
namespace {

struct Toy {
    int slices = 0;
    float scale = 0.0f;
    bool scaleAuto = false;
    bool soft = true;
    bool noEdges = false;  // zero is on: edges=off sets it
    enum class Shade : unsigned char { Seam, Smooth } shade = Shade::Seam;
};

const SettingField<Toy> kToyFields[] = {
    {{.key = "slices", .help = "slices", .type = SettingType::Integer, .min = 4, .max = 32}, &setInteger<&Toy::slices>},
    {{.key = "scale", .help = "scale", .type = SettingType::Number, .min = 0.0625, .max = 1.0, .words = {"auto"}},
     &setNumberOrAuto<&Toy::scale, &Toy::scaleAuto>},
    {{.key = "soft", .help = "soft", .type = SettingType::Boolean, .tiers = kTierExact}, &setBoolean<&Toy::soft>},
    {{.key = "shade", .help = "shade", .type = SettingType::Choice, .words = {"seam", "smooth"}}, &setChoice<&Toy::shade>},
    {{.key = "edges", .help = "edges", .type = SettingType::Boolean}, &setBooleanOff<&Toy::noEdges>},
};

Settings toySettings() {
    Settings s;
    s.declare(qualityTierSpec());
    for (const SettingSpec& spec : specsOf(kToyFields)) s.declare(spec);
    return s;
}

std::string refusal(const Settings& s, const std::string& key) {
    try {
        (void)s.read(key);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

TEST(Settings, ExplicitValuesApplyOnTopOfTheTiersStruct) {
    Settings s = toySettings();
    s.set("slices", "8");
    s.set("shade", "smooth");
    const Toy t = readFields<Toy>(s, kToyFields, Toy{.slices = 16, .scale = 0.5f});
    EXPECT_EQ(t.slices, 8);
    EXPECT_EQ(t.scale, 0.5f) << "unset keys keep the tier's value";
    EXPECT_EQ(t.shade, Toy::Shade::Smooth);
    s.set("scale", "auto");
    const Toy automatic = readFields<Toy>(s, kToyFields, Toy{.scale = 0.5f});
    EXPECT_TRUE(automatic.scaleAuto) << "a word reaches the applier";
    EXPECT_EQ(automatic.scale, 0.5f) << "auto keeps the tier's number";
    s.set("scale", "0.25");
    const Toy number = readFields<Toy>(s, kToyFields, Toy{.scale = 0.5f, .scaleAuto = true});
    EXPECT_FALSE(number.scaleAuto) << "a number clears auto";
    EXPECT_EQ(number.scale, 0.25f);
    s.set("edges", "off");
    EXPECT_TRUE(readFields<Toy>(s, kToyFields, Toy{}).noEdges) << "off sets a field whose zero is on";
    s.set("edges", "on");
    EXPECT_FALSE(readFields<Toy>(s, kToyFields, Toy{.noEdges = true}).noEdges);
}

TEST(Settings, ValuesOutsideTheSpecAreRefusedNamingOriginKeyAndRange) {
    Settings s = toySettings();
    s.set("slices", "999", "scene.gltf: node \"fog\": render.slices");
    const std::string message = refusal(s, "slices");
    EXPECT_NE(message.find("scene.gltf: node \"fog\": render.slices"), std::string::npos) << message;
    EXPECT_NE(message.find("4..32"), std::string::npos) << message;
    s.set("scale", "1e300");
    EXPECT_LT(refusal(s, "scale").size(), 160u) << "a range message stays one short line: " << refusal(s, "scale");
    s.set("scale", "nan");
    EXPECT_NE(refusal(s, "scale").find("not a finite number"), std::string::npos);
    s.set("shade", "bumpy");
    EXPECT_NE(refusal(s, "shade").find("seam or smooth"), std::string::npos) << refusal(s, "shade");
    EXPECT_THROW(s.validate(), InputError) << "validate checks every key that was set";
}

TEST(Settings, BooleansAreOnOffOrTrueFalseOnly) {
    Settings s = toySettings();
    for (const char* accepted : {"on", "off", "true", "false"}) {
        s.set("soft", accepted);
        EXPECT_NO_THROW((void)s.read("soft")) << accepted;
    }
    for (const char* refused : {"yes", "1", "ON", ""}) {
        s.set("soft", refused);
        EXPECT_THROW((void)s.read("soft"), InputError) << refused;
    }
}

TEST(Settings, AnUndeclaredKeyIsRefusedListingTheKnownOnes) {
    Settings s = toySettings();
    try {
        s.set("slice", "8");
        FAIL() << "an undeclared key was accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("slices"), std::string::npos) << e.what();
    }
}

TEST(Settings, DeclaringAKeyTwiceWithAnotherShapeIsAProgrammingError) {
    Settings s = toySettings();
    EXPECT_NO_THROW(s.declare(kToyFields[0].spec));
    SettingSpec other = kToyFields[0].spec;
    other.max = 64;
    EXPECT_THROW(s.declare(other), std::logic_error);
}

TEST(Settings, SceneDefaultsYieldToTheCommandLine) {
    Settings s = toySettings();
    s.set("quality", "exact", "--quality");
    s.setDefault("quality", "fast", "scene.gltf: render.quality");
    EXPECT_EQ(s.text("quality"), "exact");
    EXPECT_EQ(s.origin("quality"), "--quality");
    EXPECT_EQ(readQualityTier(s), QualityTier::Exact);
}

TEST(Settings, TheTierIsExactUnlessSet) {
    Settings s = toySettings();
    EXPECT_EQ(readQualityTier(s), QualityTier::Exact);
    s.set("quality", "fast");
    EXPECT_EQ(readQualityTier(s), QualityTier::Fast);
    EXPECT_EQ(readQualityTier(Settings{}), QualityTier::Exact) << "nothing declared quality";
}

TEST(Settings, TheDescriptionSaysWhereAKeyActs) {
    SettingSpec spec = kToyFields[2].spec;
    spec.modes = {"particles"};
    const std::string line = describeSetting(spec);
    EXPECT_NE(line.find("on or off"), std::string::npos) << line;
    EXPECT_NE(line.find("particles"), std::string::npos) << line;
    EXPECT_NE(line.find("exact"), std::string::npos) << line;
    EXPECT_TRUE(settingActsIn(spec, "particles", kTierExact));
    EXPECT_FALSE(settingActsIn(spec, "particles", kTierFast));
    EXPECT_FALSE(settingActsIn(spec, "blocks", kTierExact));
}

// A field whose effect another key turns off declares it (SettingField::acts): its spec's tiers
// follow from the tiers' own values, and idleKeys names it where it does not act.
struct Lit {
    bool perFragment = true;
    bool soft = true;
    static Lit forTier(QualityTier tier) { return {.perFragment = tier == QualityTier::Exact}; }
};
const SettingField<Lit> kLitFields[] = {
    {{.key = "per_fragment", .help = "per fragment", .type = SettingType::Boolean}, &setBoolean<&Lit::perFragment>},
    {{.key = "soft", .help = "soft", .type = SettingType::Boolean, .actsWhen = "with per_fragment=on"}, &setBoolean<&Lit::soft>,
     [](const Lit& l) { return l.perFragment; }},
};

TEST(SettingField, ActsDerivesTheTiersAndNamesIdleKeys) {
    const std::vector<SettingSpec> specs = specsOf(kLitFields);
    EXPECT_EQ(specs[0].tiers, 0u);
    EXPECT_EQ(specs[1].tiers, kTierExact);
    EXPECT_NE(describeSetting(specs[1]).find("tier exact; acts only with per_fragment=on"), std::string::npos) << describeSetting(specs[1]);
    EXPECT_TRUE(idleKeys(kLitFields, Lit::forTier(QualityTier::Exact)).empty());
    EXPECT_EQ(idleKeys(kLitFields, Lit::forTier(QualityTier::Fast)), std::vector<std::string>{"soft"});
}

TEST(Settings, DefaultsAreToldApartFromTheUsersValues) {
    Settings s = toySettings();
    s.set("slices", "8", "--set");
    s.setDefault("scale", "0.5", "scene.gltf: render.scale");
    s.setDefault("slices", "16", "scene.gltf: render.slices");  // the command line wins
    EXPECT_FALSE(s.isDefault("slices"));
    EXPECT_TRUE(s.isDefault("scale"));
    s.set("scale", "0.25", "--set");
    EXPECT_FALSE(s.isDefault("scale"));
}

// A typed value is repeated back at a readable length, never 300 digits.
TEST(Settings, LongValuesAreCutInMessages) {
    Settings s = toySettings();
    s.set("slices", std::string(300, '9'));
    const std::string message = refusal(s, "slices");
    EXPECT_NE(message.find("outside its range"), std::string::npos) << message;
    EXPECT_NE(message.find("300 characters"), std::string::npos) << message;
    EXPECT_LT(message.size(), 160u) << message;
}

}  // namespace
}  // namespace nimbus
