// Tests plugins/participating_media/core/src/emitters/emitter_parse.cpp and emitter_presets.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "nimbus/base/error.h"
#include "nimbus/media/emitter_desc.h"

namespace nimbus::media {
namespace {

using Json = nlohmann::json;

const ParseContext kWhere{"scenes/campfire.gltf", 3, "fire"};
const double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string errorOf(const Json& object) {
    try {
        parseEmitter(object, kWhere);
    } catch (const InputError& e) {
        return e.what();
    }
    return "(accepted)";
}

TEST(EmitterParse, EmptyObjectIsTheDocumentedDefault) {
    const EmitterDesc d = parseEmitter(Json::object(), kWhere);
    EXPECT_EQ(d, EmitterDesc{});
    EXPECT_EQ(d.preset, EmitterPreset::None);
    EXPECT_EQ(d.maxParticles, 1000u);
    EXPECT_EQ(d.rate, 10.0);
    EXPECT_TRUE(std::isinf(d.stop));
    EXPECT_EQ(d.radius.at(0.3f), 0.5f);
    EXPECT_TRUE(d.albedoOverLife.empty());
    EXPECT_TRUE(d.emissionOverLife.empty());
}

TEST(EmitterParse, EveryPresetParsesToItsDescription) {
    for (EmitterPreset p : kEmitterPresets) {
        SCOPED_TRACE(std::string(presetName(p)));
        const EmitterDesc d = parseEmitter({{"preset", presetName(p)}}, kWhere);
        EXPECT_EQ(d, presetDesc(p));
        EXPECT_EQ(d.preset, p);
        // Every preset is a sane emitter: it lives, it is visible, it keeps to its pool.
        EXPECT_GT(d.lifetimeMin, 0.0);
        EXPECT_LE(d.lifetimeMin, d.lifetimeMax);
        EXPECT_TRUE(d.rate > 0.0 || !d.bursts.empty());
        EXPECT_LE(d.rate * d.lifetimeMax, static_cast<double>(d.maxParticles));
        EXPECT_FALSE(d.albedoOverLife.empty());
        EXPECT_EQ(d.density.at(1.0f), 0.0f) << "particles fade out before they die";
    }
}

TEST(EmitterParse, PresetsLookLikeTheirPhenomenon) {
    const EmitterDesc smoke = presetDesc(EmitterPreset::Smoke);
    EXPECT_GE(smoke.albedoOverLife.at(0.0f).x, 0.6f);
    EXPECT_LE(smoke.albedoOverLife.at(1.0f).x, 0.8f);
    EXPECT_NEAR(smoke.radius.at(1.0f) / smoke.radius.at(0.0f), 3.0f, 1e-6f);
    EXPECT_GT(smoke.buoyancy, 0.0);

    const EmitterDesc steam = presetDesc(EmitterPreset::Steam);
    EXPECT_GE(steam.albedoOverLife.at(0.5f).x, 0.9f);
    EXPECT_GT(steam.buoyancy / steam.drag, smoke.buoyancy / smoke.drag) << "steam rises faster";
    EXPECT_LT(steam.lifetimeMax, smoke.lifetimeMin) << "and is gone sooner";

    const EmitterDesc trail = presetDesc(EmitterPreset::VaporTrail);
    EXPECT_GT(trail.lifetimeMin, smoke.lifetimeMax) << "long life";
    EXPECT_LT(trail.buoyancy, 0.1);
    EXPECT_LT(trail.radius.at(0.0f), trail.radius.at(1.0f));

    const EmitterDesc fire = presetDesc(EmitterPreset::Fire);
    EXPECT_LE(fire.albedoOverLife.at(0.5f).x, 0.3f);
    const glm::vec3 young = fire.emissionOverLife.at(0.0f), old = fire.emissionOverLife.at(1.0f);
    EXPECT_GT(young.x, 1.0f);
    EXPECT_GT(young.y, young.z) << "orange at birth";
    EXPECT_GT(old.x, 4.0f * old.y) << "dark red at death";
    EXPECT_LT(old.x, young.x);
    EXPECT_LT(fire.lifetimeMax, 1.5);

    const EmitterDesc boom = presetDesc(EmitterPreset::Explosion);
    ASSERT_EQ(boom.bursts.size(), 1u);
    EXPECT_EQ(boom.bursts[0].time, 0.0);
    EXPECT_EQ(boom.spread, std::numbers::pi);
    EXPECT_GT(boom.emissionOverLife.at(0.0f).x, 10.0f) << "fireball";
    EXPECT_EQ(boom.emissionOverLife.at(0.5f), glm::vec3(0.0f)) << "cooled into smoke";
    EXPECT_GT(boom.buoyancy, 0.0) << "the smoke rises";
}

TEST(EmitterParse, ExplicitFieldsOverrideThePresetAndObjectsMerge) {
    const Json object = {{"preset", "fire"}, {"rate", 5}, {"shape", {{"radius", 0.5}}},
                         {"turbulence", {{"strength", 0}}}, {"lifetime", 3}, {"seed", 77}};
    const EmitterDesc d = parseEmitter(object, kWhere);
    EmitterDesc expected = presetDesc(EmitterPreset::Fire);
    expected.rate = 5.0;
    expected.shapeRadius = 0.5;  // the preset's disc, with the file's radius
    expected.turbulence.strength = 0.0;
    expected.lifetimeMin = expected.lifetimeMax = 3.0;
    expected.seed = 77;
    EXPECT_EQ(d, expected);
    EXPECT_EQ(d.shape, SpawnShape::Disc);
    EXPECT_EQ(d.turbulence.scale, presetDesc(EmitterPreset::Fire).turbulence.scale);
}

TEST(EmitterParse, ReadsEveryField) {
    const Json object = {
        {"seed", 4294967295u}, {"max_particles", 5000}, {"rate", 120.5},
        {"bursts", {{{"time", 0.5}, {"count", 40}}, {{"count", 2}}}}, {"start", 0.25}, {"stop", 9},
        {"lifetime", {1.5, 2.5}}, {"shape", {{"type", "box"}, {"size", {1, 2, 3}}}}, {"velocity", {0, 2, -1}},
        {"spread", 0.4}, {"speed_jitter", 0.1}, {"inherit_velocity", 0.5},
        {"radius", {{0, 0.2}, {0.5, 0.4}, {1, 0.3}}}, {"radius_jitter", 0.25},
        {"density", {{0, 0}, {0.2, 1}, {1, 0}}}, {"buoyancy", -0.5}, {"drag", 0.3}, {"wind", {1, 0, 0.5}},
        {"turbulence", {{"strength", 0.7}, {"scale", 2}, {"speed", 0.1}}},
        {"albedo_over_life", {{0, 0.5, 0.5, 0.5}, {1, 0.9, 0.8, 0.7}}},
        {"emission_over_life", {{0, 3, 1, 0}}}};
    const EmitterDesc d = parseEmitter(object, kWhere);
    EXPECT_EQ(d.seed, 4294967295u);
    EXPECT_EQ(d.maxParticles, 5000u);
    EXPECT_EQ(d.rate, 120.5);
    ASSERT_EQ(d.bursts.size(), 2u);
    EXPECT_EQ(d.bursts[0], (EmitterBurst{0.5, 40}));
    EXPECT_EQ(d.bursts[1], (EmitterBurst{0.0, 2}));
    EXPECT_EQ(d.start, 0.25);
    EXPECT_EQ(d.stop, 9.0);
    EXPECT_EQ(d.lifetimeMin, 1.5);
    EXPECT_EQ(d.lifetimeMax, 2.5);
    EXPECT_EQ(d.shape, SpawnShape::Box);
    EXPECT_EQ(d.shapeSize, glm::dvec3(1, 2, 3));
    EXPECT_EQ(d.velocity, glm::dvec3(0, 2, -1));
    EXPECT_EQ(d.spread, 0.4);
    EXPECT_EQ(d.speedJitter, 0.1);
    EXPECT_EQ(d.inheritVelocity, 0.5);
    EXPECT_FLOAT_EQ(d.radius.at(0.25f), 0.3f);
    EXPECT_EQ(d.radiusJitter, 0.25);
    EXPECT_FLOAT_EQ(d.density.at(0.6f), 0.5f);
    EXPECT_EQ(d.buoyancy, -0.5);
    EXPECT_EQ(d.drag, 0.3);
    EXPECT_EQ(d.wind, glm::dvec3(1, 0, 0.5));
    EXPECT_EQ(d.turbulence, (EmitterTurbulence{0.7, 2.0, 0.1}));
    EXPECT_EQ(d.albedoOverLife.at(1.0f), glm::vec3(0.9f, 0.8f, 0.7f));
    EXPECT_EQ(d.emissionOverLife.at(0.7f), glm::vec3(3, 1, 0));
}

TEST(EmitterParse, MediumKeepsTheNodesColoursOverAPreset) {
    const EmitterDesc d = parseEmitter({{"preset", "fire"}, {"albedo_over_life", "medium"}, {"emission_over_life", "medium"}}, kWhere);
    EXPECT_TRUE(d.albedoOverLife.empty());
    EXPECT_TRUE(d.emissionOverLife.empty());
}

TEST(EmitterParse, IntegralFloatsAreIntegers) {
    EXPECT_EQ(parseEmitter({{"max_particles", 64.0}}, kWhere).maxParticles, 64u);
}

TEST(EmitterParse, MessageNamesFileNodeAndField) {
    EXPECT_EQ(errorOf({{"lifetime", {0.0, 1.0}}}),
              "scenes/campfire.gltf: node \"fire\" (nodes[3]): emitter.lifetime[0]: must be in (0.0, 100000.0], not 0.0");
    EXPECT_EQ(errorOf(Json::array()), "scenes/campfire.gltf: node \"fire\" (nodes[3]): emitter: must be an object");
    const ParseContext unnamed{"a.glb", 0, ""};
    try {
        parseEmitter({{"rate", -1}}, unnamed);
        FAIL() << "accepted";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()).rfind("a.glb: nodes[0]: emitter.rate: ", 0), 0u) << e.what();
    }
}

struct Refusal {
    Json object;
    std::string field;    // expected after "emitter"
    std::string problem;  // a part of the reason
};

TEST(EmitterParse, RefusesInvalidValuesNamingTheField) {
    const std::vector<Refusal> cases = {
        {{{"rate", kNaN}}, ".rate", "finite"},
        {{{"rate", -1}}, ".rate", "must be in [0.0, 1000000.0]"},
        {{{"rate", 2e6}}, ".rate", "1000000"},
        {{{"rate", "fast"}}, ".rate", "must be a number"},
        {{{"rate", true}}, ".rate", "must be a number"},
        {{{"max_particles", 2000000}}, ".max_particles", "[1, 1000000]"},
        {{{"max_particles", 0}}, ".max_particles", "integer"},
        {{{"max_particles", 10.5}}, ".max_particles", "integer"},
        {{{"seed", -1}}, ".seed", "integer"},
        {{{"seed", 5000000000ll}}, ".seed", "4294967295"},
        {{{"seed", "7"}}, ".seed", "integer"},
        {{{"preset", "lava"}}, ".preset", "unknown value \"lava\""},
        {{{"preset", 3}}, ".preset", "must be a string"},
        {{{"speed", 3}}, ".speed", "unknown key"},
        {{{"shape", {{"type", "cone"}}}}, ".shape.type", "unknown value \"cone\""},
        {{{"shape", {{"type", "sphere"}, {"radius", -1}}}}, ".shape.radius", "(0.0, 10000.0]"},
        {{{"shape", {{"type", "disc"}, {"radius", kNaN}}}}, ".shape.radius", "finite"},
        {{{"shape", {{"type", "point"}, {"radius", 1}}}}, ".shape.radius", "applies only"},
        {{{"shape", {{"type", "sphere"}, {"size", {1, 1, 1}}}}}, ".shape.size", "applies only"},
        {{{"shape", {{"type", "box"}, {"size", {1, 0, 1}}}}}, ".shape.size[1]", "(0.0"},
        {{{"shape", {{"colour", 1}}}}, ".shape.colour", "unknown key"},
        {{{"shape", "sphere"}}, ".shape", "must be an object"},
        {{{"lifetime", 0}}, ".lifetime", "(0.0"},
        {{{"lifetime", {3, 1}}}, ".lifetime", "less than min"},
        {{{"lifetime", {1}}}, ".lifetime", "[min, max]"},
        {{{"lifetime", {1, kNaN}}}, ".lifetime[1]", "finite"},
        {{{"velocity", {0, 1}}}, ".velocity", "3 numbers"},
        {{{"velocity", {0, kNaN, 0}}}, ".velocity[1]", "finite"},
        {{{"spread", 4}}, ".spread", "3.14159"},
        {{{"speed_jitter", 1.5}}, ".speed_jitter", "[0.0, 1.0]"},
        {{{"inherit_velocity", -0.1}}, ".inherit_velocity", "[0.0, 1.0]"},
        {{{"radius", -0.5}}, ".radius", "(0.0"},
        {{{"radius", {{0, 1}, {0.5, 0}}}}, ".radius[1][1]", "(0.0"},
        {{{"radius", "big"}}, ".radius", "a number or an array"},
        {{{"radius_jitter", 1}}, ".radius_jitter", "< 1"},
        {{{"density", {{0.5, 1}, {0.5, 1}}}}, ".density[1][0]", "increase strictly"},
        {{{"density", {{1.5, 1}}}}, ".density[0][0]", "[0.0, 1.0]"},
        {{{"density", Json::array()}}, ".density", "1 to 256 keys"},
        {{{"density", {{0, -1}}}}, ".density[0][1]", "[0.0"},
        {{{"density", {{0, 1, 2}}}}, ".density[0]", "[age, value]"},
        {{{"albedo_over_life", {{0, 1.2, 0.5, 0.5}}}}, ".albedo_over_life[0][1]", "[0.0, 1.0]"},
        {{{"albedo_over_life", "grey"}}, ".albedo_over_life", "unknown value \"grey\""},
        {{{"emission_over_life", {{0, -1, 0, 0}}}}, ".emission_over_life[0][1]", "[0.0"},
        {{{"emission_over_life", {{0, 1, 0}}}}, ".emission_over_life[0]", "[age, r, g, b]"},
        {{{"bursts", {{{"time", 0}}}}}, ".bursts[0].count", "is required"},
        {{{"bursts", {{{"count", 300}}}}, {"max_particles", 100}}, ".bursts[0].count", "more than max_particles"},
        {{{"bursts", {{{"count", 1}, {"when", 2}}}}}, ".bursts[0].when", "unknown key"},
        {{{"bursts", {{{"count", 1}, {"time", -1}}}}}, ".bursts[0].time", "[0.0"},
        {{{"bursts", {{"count", 1}}}}, ".bursts", "array of at most"},
        {{{"start", 2}, {"stop", 1}}, ".stop", "later than start"},
        {{{"start", -2}}, ".start", "[0.0"},
        {{{"drag", -1}}, ".drag", "[0.0, 1000.0]"},
        {{{"buoyancy", 1e9}}, ".buoyancy", "[-1000.0, 1000.0]"},
        {{{"wind", {0, 0, 1e9}}}, ".wind[2]", "10000.0"},
        {{{"turbulence", {{"scale", 0}}}}, ".turbulence.scale", "(0.0"},
        {{{"turbulence", {{"strength", kNaN}}}}, ".turbulence.strength", "finite"},
        {{{"turbulence", {{"octaves", 3}}}}, ".turbulence.octaves", "unknown key"},
    };
    for (const Refusal& c : cases) {
        const std::string message = errorOf(c.object);
        SCOPED_TRACE(c.object.dump());
        const std::string prefix = "scenes/campfire.gltf: node \"fire\" (nodes[3]): emitter" + c.field + ": ";
        EXPECT_EQ(message.rfind(prefix, 0), 0u) << message;
        EXPECT_NE(message.find(c.problem), std::string::npos) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos);
    }
}

TEST(EmitterParse, PresetFieldsAreCheckedAcrossFields) {
    // The explosion's burst of 200 no longer fits a pool of 50: refused, not silently dropped.
    EXPECT_NE(errorOf({{"preset", "explosion"}, {"max_particles", 50}}).find("emitter.bursts[0].count"), std::string::npos);
    // A stop before the preset's start.
    EXPECT_NE(errorOf({{"start", 3}, {"stop", 3}}).find("emitter.stop"), std::string::npos);
}

TEST(EmitterCurve, InterpolatesLinearlyAndHoldsTheEnds) {
    const Curve<float> c{{0.2f, 0.6f, 1.0f}, {1.0f, 3.0f, 2.0f}};
    EXPECT_EQ(c.at(0.0f), 1.0f);
    EXPECT_EQ(c.at(0.2f), 1.0f);
    EXPECT_FLOAT_EQ(c.at(0.4f), 2.0f);
    EXPECT_EQ(c.at(0.6f), 3.0f);
    EXPECT_FLOAT_EQ(c.at(0.8f), 2.5f);
    EXPECT_EQ(c.at(1.0f), 2.0f);
    EXPECT_EQ(c.at(1.5f), 2.0f);
    const Curve<glm::vec3> color{{0.0f, 1.0f}, {glm::vec3(0.0f), glm::vec3(1.0f, 2.0f, 4.0f)}};
    EXPECT_EQ(color.at(0.5f), glm::vec3(0.5f, 1.0f, 2.0f));
    EXPECT_EQ(Curve<float>::constant(7.0f).at(0.9f), 7.0f);
}

}  // namespace
}  // namespace nimbus::media
