// The presets of McReynolds and Blythe's natural phenomena (smoke puffs, steam, vapour trails, fire,
// explosions) as full emitter descriptions. Values are chosen for metre-scale scenes lit by the default 3 lux
// sun (a white Lambert surface at radiance ≈ 1): docs/scene-format.md lists them with the medium to pair them
// with.
#include <numbers>

#include "nimbus/media/emitter_desc.h"

namespace nimbus::media {
namespace {

Curve<float> curve(std::initializer_list<std::pair<float, float>> keys) {
    Curve<float> c;
    for (const auto& [age, value] : keys) {
        c.ages.push_back(age);
        c.values.push_back(value);
    }
    return c;
}

Curve<glm::vec3> colors(std::initializer_list<std::pair<float, glm::vec3>> keys) {
    Curve<glm::vec3> c;
    for (const auto& [age, value] : keys) {
        c.ages.push_back(age);
        c.values.push_back(value);
    }
    return c;
}

// Grey puffs that rise slowly, grow 3× and fade in then out (McReynolds and Blythe §1).
EmitterDesc smoke() {
    EmitterDesc d;
    d.preset = EmitterPreset::Smoke;
    d.maxParticles = 256;
    d.rate = 12.0;
    d.lifetimeMin = 4.0;
    d.lifetimeMax = 6.0;
    d.shape = SpawnShape::Sphere;
    d.shapeRadius = 0.15;
    d.velocity = {0.0, 0.6, 0.0};
    d.spread = 0.35;
    d.speedJitter = 0.3;
    d.radius = curve({{0.0f, 0.25f}, {1.0f, 0.75f}});
    d.radiusJitter = 0.2;
    d.density = curve({{0.0f, 0.0f}, {0.1f, 1.0f}, {0.6f, 0.7f}, {1.0f, 0.0f}});
    d.buoyancy = 0.4;  // with drag 0.8: rises at 0.5 m/s once the initial push has decayed
    d.drag = 0.8;
    d.turbulence = {0.25, 1.0, 0.3};
    d.albedoOverLife = colors({{0.0f, glm::vec3(0.65f)}, {1.0f, glm::vec3(0.75f)}});
    return d;
}

// White, bright, quick: rises fast from a small vent and is gone within two seconds.
EmitterDesc steam() {
    EmitterDesc d;
    d.preset = EmitterPreset::Steam;
    d.maxParticles = 256;
    d.rate = 30.0;
    d.lifetimeMin = 1.2;
    d.lifetimeMax = 2.0;
    d.shape = SpawnShape::Disc;
    d.shapeRadius = 0.1;
    d.velocity = {0.0, 1.5, 0.0};
    d.spread = 0.2;
    d.speedJitter = 0.2;
    d.radius = curve({{0.0f, 0.1f}, {1.0f, 0.5f}});
    d.radiusJitter = 0.2;
    d.density = curve({{0.0f, 1.0f}, {0.3f, 0.6f}, {1.0f, 0.0f}});
    d.buoyancy = 1.5;
    d.drag = 1.0;
    d.turbulence = {0.3, 0.5, 0.5};
    d.albedoOverLife = colors({{0.0f, glm::vec3(0.95f)}});
    return d;
}

// Left behind by a moving node (McReynolds and Blythe §2): particles stay where they were born, widen slowly
// and fade over ten seconds. The spacing of the trail is (node speed) / rate.
EmitterDesc vaporTrail() {
    EmitterDesc d;
    d.preset = EmitterPreset::VaporTrail;
    d.maxParticles = 4096;
    d.rate = 200.0;
    d.lifetimeMin = 8.0;
    d.lifetimeMax = 12.0;
    d.shape = SpawnShape::Sphere;
    d.shapeRadius = 0.05;
    d.radius = curve({{0.0f, 0.3f}, {1.0f, 1.2f}});
    d.radiusJitter = 0.15;
    d.density = curve({{0.0f, 1.0f}, {0.7f, 0.5f}, {1.0f, 0.0f}});
    d.buoyancy = 0.05;
    d.drag = 0.5;
    d.turbulence = {0.15, 3.0, 0.2};
    d.albedoOverLife = colors({{0.0f, glm::vec3(0.92f)}});
    return d;
}

// Small, short-lived, emissive particles rising fast; orange at birth, dark red as they die (McReynolds and Blythe §3).
EmitterDesc fire() {
    EmitterDesc d;
    d.preset = EmitterPreset::Fire;
    d.maxParticles = 256;
    d.rate = 60.0;
    d.lifetimeMin = 0.6;
    d.lifetimeMax = 1.0;
    d.shape = SpawnShape::Disc;
    d.shapeRadius = 0.2;
    d.velocity = {0.0, 1.0, 0.0};
    d.spread = 0.25;
    d.speedJitter = 0.3;
    d.radius = curve({{0.0f, 0.15f}, {0.4f, 0.2f}, {1.0f, 0.08f}});
    d.radiusJitter = 0.3;
    d.density = curve({{0.0f, 0.5f}, {0.15f, 1.0f}, {1.0f, 0.0f}});
    d.buoyancy = 4.0;  // with drag 2: 2 m/s
    d.drag = 2.0;
    d.turbulence = {0.4, 0.4, 1.0};
    d.albedoOverLife = colors({{0.0f, glm::vec3(0.2f)}});
    d.emissionOverLife = colors({{0.0f, {4.0f, 2.0f, 0.6f}}, {0.5f, {2.5f, 0.8f, 0.15f}}, {1.0f, {0.4f, 0.05f, 0.01f}}});
    return d;
}

// One burst (McReynolds and Blythe §4): a fireball that expands fast, glows for about half a second, then cools
// into dark smoke that rises as a column (buoyancy against drag) and fades.
EmitterDesc explosion() {
    EmitterDesc d;
    d.preset = EmitterPreset::Explosion;
    d.maxParticles = 256;
    d.rate = 0.0;
    d.bursts = {{0.0, 200}};
    d.lifetimeMin = 2.5;
    d.lifetimeMax = 5.0;
    d.shape = SpawnShape::Sphere;
    d.shapeRadius = 0.3;
    d.velocity = {0.0, 6.0, 0.0};
    d.spread = std::numbers::pi;  // every direction
    d.speedJitter = 0.7;
    d.radius = curve({{0.0f, 0.35f}, {0.1f, 0.9f}, {1.0f, 1.8f}});
    d.radiusJitter = 0.3;
    d.density = curve({{0.0f, 1.0f}, {0.6f, 0.7f}, {1.0f, 0.0f}});
    d.buoyancy = 2.5;  // with drag 2.5: the cooled smoke rises at 1 m/s
    d.drag = 2.5;      // the initial 6 m/s decays in 0.4 s: the fireball stops at ~2 m
    d.turbulence = {0.5, 1.5, 0.5};
    d.albedoOverLife = colors({{0.0f, glm::vec3(0.15f)}, {0.3f, glm::vec3(0.4f)}, {1.0f, glm::vec3(0.5f)}});
    d.emissionOverLife = colors({{0.0f, {20.0f, 10.0f, 3.0f}},
                                 {0.05f, {10.0f, 4.0f, 0.8f}},
                                 {0.15f, {1.5f, 0.3f, 0.05f}},
                                 {0.3f, glm::vec3(0.0f)}});
    return d;
}

}  // namespace

std::string_view presetName(EmitterPreset preset) {
    switch (preset) {
        case EmitterPreset::Smoke: return "smoke";
        case EmitterPreset::Steam: return "steam";
        case EmitterPreset::VaporTrail: return "vapor_trail";
        case EmitterPreset::Fire: return "fire";
        case EmitterPreset::Explosion: return "explosion";
        case EmitterPreset::None: break;
    }
    return "none";
}

EmitterDesc presetDesc(EmitterPreset preset) {
    switch (preset) {
        case EmitterPreset::Smoke: return smoke();
        case EmitterPreset::Steam: return steam();
        case EmitterPreset::VaporTrail: return vaporTrail();
        case EmitterPreset::Fire: return fire();
        case EmitterPreset::Explosion: return explosion();
        case EmitterPreset::None: break;
    }
    return EmitterDesc{};
}

}  // namespace nimbus::media
