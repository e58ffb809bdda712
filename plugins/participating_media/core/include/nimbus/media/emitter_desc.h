#pragma once
// The "emitter" object of a node's NIMBUS_participating_media extension (docs/scene-format.md):
// what an emitter spawns, how particles move, grow, fade and change colour over their life.
// parseEmitter() validates the JSON and fills every field the file leaves out from the preset (or
// from the defaults below when there is no preset). Every refusal is one nimbus::InputError naming
// the file, the node and the field.
//
// Does not: simulate (emitter_simulation.h); read the node's "medium" (media_scene.h).
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

namespace nimbus::media {

// Bounds beyond which a value is refused as absurd (documented in docs/scene-format.md).
inline constexpr std::uint32_t kMaxEmitterParticles = 1'000'000;
inline constexpr double kMaxEmitterRate = 1.0e6;      // particles per second
inline constexpr std::size_t kMaxEmitterBursts = 1024;
inline constexpr std::size_t kMaxCurveKeys = 256;

enum class EmitterPreset : std::uint8_t { None, Smoke, Steam, VaporTrail, Fire, Explosion };
enum class SpawnShape : std::uint8_t { Point, Sphere, Box, Disc };

// A piecewise-linear function of normalised age a = age / lifetime in [0, 1]. Keys are strictly
// increasing in [0, 1]; before the first key and after the last the end values hold. Empty means
// "not given" (only meaningful for the colour curves, which then fall back to the medium).
template <class T>
struct Curve {
    std::vector<float> ages;
    std::vector<T> values;

    bool empty() const { return ages.empty(); }
    bool operator==(const Curve&) const = default;

    T at(float age) const {
        if (ages.empty()) return T(0);
        if (!(age > ages.front())) return values.front();
        if (age >= ages.back()) return values.back();
        const std::size_t hi = static_cast<std::size_t>(std::upper_bound(ages.begin(), ages.end(), age) - ages.begin());
        const std::size_t lo = hi - 1;
        const float f = (age - ages[lo]) / (ages[hi] - ages[lo]);
        return values[lo] + (values[hi] - values[lo]) * f;
    }

    static Curve constant(T value) { return Curve{{0.0f}, {value}}; }
};

struct EmitterBurst {
    double time = 0.0;         // s, >= 0; fires once, in the step whose interval holds it
    std::uint32_t count = 0;   // particles, 1 .. max_particles
    bool operator==(const EmitterBurst&) const = default;
};

struct EmitterTurbulence {
    double strength = 0.0;  // m/s, RMS speed of the curl-noise velocity; 0 = off
    double scale = 1.0;     // m, size of the swirls
    double speed = 0.0;     // m/s, how fast the pattern evolves (each potential drifts at this speed)
    bool operator==(const EmitterTurbulence&) const = default;
};

// A default-constructed EmitterDesc is the documented "no preset" emitter. Units: metres, seconds.
// Vectors marked "local" are in the emitter node's frame (its whole linear part applies, so a
// scaled node has a scaled shape and speed); "world" ones are not transformed.
struct EmitterDesc {
    EmitterPreset preset = EmitterPreset::None;
    std::uint32_t seed = 0;
    std::uint32_t maxParticles = 1000;  // the pool; spawns beyond it are dropped
    double rate = 10.0;                 // particles/s while start <= t < stop
    std::vector<EmitterBurst> bursts;
    double start = 0.0;                                       // s
    double stop = std::numeric_limits<double>::infinity();    // s; infinity = never
    double lifetimeMin = 2.0, lifetimeMax = 2.0;              // s, uniform in [min, max]
    SpawnShape shape = SpawnShape::Point;
    double shapeRadius = 0.5;       // m (sphere: volume; disc: local XZ plane, normal +Y)
    glm::dvec3 shapeSize{1.0};      // m, full edge lengths (box)
    glm::dvec3 velocity{0.0};       // m/s, local
    double spread = 0.0;            // rad, cone half-angle around velocity, [0, π]
    double speedJitter = 0.0;       // speed × (1 ± jitter), [0, 1]
    double inheritVelocity = 0.0;   // fraction of the node's own world velocity, [0, 1]
    Curve<float> radius = Curve<float>::constant(0.5f);  // m over normalised age
    double radiusJitter = 0.0;      // per-particle radius × (1 ± jitter), [0, 1)
    Curve<float> density = Curve<float>::constant(1.0f);  // multiplies the medium's extinction
    double buoyancy = 0.0;          // m/s², along world +Y
    double drag = 0.0;              // 1/s, decay rate of the particle's own velocity
    glm::dvec3 wind{0.0};           // m/s, world; advects every particle
    EmitterTurbulence turbulence;
    Curve<glm::vec3> albedoOverLife;    // empty: the medium's albedo
    Curve<glm::vec3> emissionOverLife;  // empty: the medium's emission

    bool operator==(const EmitterDesc&) const = default;
};

// Where an emitter object sits, for error messages:
// "scenes/campfire.gltf: node "fire" (nodes[3]): emitter.lifetime: ...".
struct ParseContext {
    std::string file;
    int nodeIndex = -1;
    std::string nodeName;
    std::string field = "emitter";  // the path of the emitter object itself

    std::string object() const;
    [[noreturn]] void fail(std::string_view subField, std::string_view problem) const;
};

// Every key an emitter object may hold (the JSON schema lists exactly these).
inline constexpr std::array<std::string_view, 22> kEmitterKeys = {
    "preset", "seed", "max_particles", "rate", "bursts", "start", "stop", "lifetime", "shape", "velocity",
    "spread", "speed_jitter", "inherit_velocity", "radius", "radius_jitter", "density", "buoyancy", "drag",
    "wind", "turbulence", "albedo_over_life", "emission_over_life"};

// The preset names as written in files ("smoke", "steam", "vapor_trail", "fire", "explosion").
inline constexpr std::array<EmitterPreset, 5> kEmitterPresets = {
    EmitterPreset::Smoke, EmitterPreset::Steam, EmitterPreset::VaporTrail, EmitterPreset::Fire,
    EmitterPreset::Explosion};
std::string_view presetName(EmitterPreset preset);  // "none" for EmitterPreset::None

// The full description a preset stands for (EmitterDesc{} for None).
EmitterDesc presetDesc(EmitterPreset preset);

// Validates `object` and returns the description: preset values (or defaults), then the file's
// explicit values. Unknown keys, unknown enum values, non-finite or out-of-range numbers are
// refused with an InputError naming `where` and the field.
EmitterDesc parseEmitter(const nlohmann::json& object, const ParseContext& where);

}  // namespace nimbus::media
