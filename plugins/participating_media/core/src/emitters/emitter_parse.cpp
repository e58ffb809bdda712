// Validation of the "emitter" object (docs/scene-format.md, docs/scene-format.schema.json): the
// file's explicit values override the preset's; anything unknown or out of range is refused.
#include <cmath>
#include <numbers>
#include <string>

#include "nimbus/base/error.h"
#include "nimbus/base/log.h"
#include "nimbus/media/emitter_desc.h"

namespace nimbus::media {

std::string ParseContext::object() const {
    if (nodeIndex < 0) return nodeName.empty() ? std::string() : "node \"" + nodeName + "\"";
    const std::string index = "nodes[" + std::to_string(nodeIndex) + "]";
    return nodeName.empty() ? index : "node \"" + nodeName + "\" (" + index + ")";
}

void ParseContext::fail(std::string_view subField, std::string_view problem) const {
    std::string full = field;
    if (!subField.empty()) full += (full.empty() || subField.front() == '[' ? "" : ".") + std::string(subField);
    throwInputError(file, object(), full, problem);
}

namespace {

using Json = nlohmann::json;

constexpr double kPi = std::numbers::pi;
constexpr double kMaxTime = 1.0e6;      // s: start, stop, burst times
constexpr double kMaxLifetime = 1.0e5;  // s
constexpr double kMaxLength = 1.0e4;    // m: shape sizes, radii
constexpr double kMaxSpeed = 1.0e4;     // m/s: velocity, wind
constexpr double kMaxCoefficient = 1.0e3;  // buoyancy (m/s²), drag (1/s), turbulence strength and speed

std::string fmt(double v) { return Json(v).dump(); }

std::string element(const std::string& field, std::size_t i) { return field + "[" + std::to_string(i) + "]"; }

// A finite number in [lo, hi] (or (lo, hi] when `openLow`).
double readNumber(const Json& value, const ParseContext& where, const std::string& field, double lo, double hi,
                  bool openLow = false) {
    if (!value.is_number()) where.fail(field, "must be a number, not " + value.dump());
    const double v = value.get<double>();
    if (!std::isfinite(v)) where.fail(field, "must be finite");
    const bool low = openLow ? v > lo : v >= lo;
    if (!low || v > hi)
        where.fail(field, "must be in " + std::string(openLow ? "(" : "[") + fmt(lo) + ", " + fmt(hi) + "], not " + fmt(v));
    return v;
}

std::uint64_t readInteger(const Json& value, const ParseContext& where, const std::string& field, std::uint64_t lo,
                          std::uint64_t hi) {
    if (value.is_number_unsigned() || value.is_number_integer()) {
        if (value.is_number_integer() && !value.is_number_unsigned() && value.get<std::int64_t>() < 0)
            where.fail(field, "must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], not " +
                                  value.dump());
        const std::uint64_t v = value.get<std::uint64_t>();
        if (v < lo || v > hi)
            where.fail(field, "must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], not " +
                                  value.dump());
        return v;
    }
    if (value.is_number_float()) {  // 3.0 is an integer in JSON Schema; 3.5 and NaN are not
        const double v = value.get<double>();
        if (std::isfinite(v) && v == std::floor(v) && v >= static_cast<double>(lo) && v <= static_cast<double>(hi))
            return static_cast<std::uint64_t>(v);
    }
    where.fail(field,
               "must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], not " + value.dump());
}

glm::dvec3 readVector(const Json& value, const ParseContext& where, const std::string& field, double limit) {
    if (!value.is_array() || value.size() != 3) where.fail(field, "must be an array of 3 numbers");
    glm::dvec3 out;
    for (std::size_t c = 0; c < 3; ++c) out[static_cast<int>(c)] = readNumber(value[c], where, element(field, c), -limit, limit);
    return out;
}

std::string readString(const Json& value, const ParseContext& where, const std::string& field) {
    if (!value.is_string()) where.fail(field, "must be a string, not " + value.dump());
    return value.get<std::string>();
}

void refuseUnknownKeys(const Json& object, const ParseContext& where, const std::string& prefix,
                       std::initializer_list<std::string_view> allowed) {
    for (auto it = object.begin(); it != object.end(); ++it) {
        if (std::find(allowed.begin(), allowed.end(), it.key()) == allowed.end())
            where.fail(prefix.empty() ? it.key() : prefix + "." + it.key(), "unknown key");
    }
}

// Curve keys [age, v...] with `Components` values each in [lo, hi] (open at lo when `openLow`).
template <class T, int Components>
Curve<T> readCurve(const Json& value, const ParseContext& where, const std::string& field, double lo, double hi,
                   bool openLow) {
    const std::string shape = Components == 1 ? "[age, value]" : "[age, r, g, b]";
    if (!value.is_array() || value.empty() || value.size() > kMaxCurveKeys)
        where.fail(field, "must be an array of 1 to " + std::to_string(kMaxCurveKeys) + " keys " + shape);
    Curve<T> curve;
    for (std::size_t k = 0; k < value.size(); ++k) {
        const std::string key = element(field, k);
        const Json& entry = value[k];
        if (!entry.is_array() || entry.size() != 1 + Components) where.fail(key, "must be a key " + shape);
        const double age = readNumber(entry[0], where, key + "[0]", 0.0, 1.0);
        if (!curve.ages.empty() && !(age > static_cast<double>(curve.ages.back())))
            where.fail(key + "[0]", "ages must increase strictly, but " + fmt(age) + " follows " + fmt(curve.ages.back()));
        T v{};
        for (int c = 0; c < Components; ++c) {
            const double x = readNumber(entry[static_cast<std::size_t>(1 + c)], where, key + "[" + std::to_string(1 + c) + "]",
                                        lo, hi, openLow);
            if constexpr (Components == 1) {
                v = static_cast<float>(x);
            } else {
                v[c] = static_cast<float>(x);
            }
        }
        curve.ages.push_back(static_cast<float>(age));
        curve.values.push_back(v);
    }
    return curve;
}

// A scalar curve, or one number for a constant.
Curve<float> readScalarCurve(const Json& value, const ParseContext& where, const std::string& field, double lo,
                             double hi, bool openLow) {
    if (value.is_number()) return Curve<float>::constant(static_cast<float>(readNumber(value, where, field, lo, hi, openLow)));
    if (!value.is_array()) where.fail(field, "must be a number or an array of keys [age, value]");
    return readCurve<float, 1>(value, where, field, lo, hi, openLow);
}

// A colour curve, or "medium" for the node's medium value (an empty curve).
Curve<glm::vec3> readColorCurve(const Json& value, const ParseContext& where, const std::string& field, double hi) {
    if (value.is_string()) {
        if (value.get<std::string>() != "medium")
            where.fail(field, "unknown value " + value.dump() + " (expected \"medium\" or an array of keys [age, r, g, b])");
        return {};
    }
    return readCurve<glm::vec3, 3>(value, where, field, 0.0, hi, false);
}

EmitterPreset readPreset(const Json& value, const ParseContext& where) {
    const std::string name = readString(value, where, "preset");
    for (EmitterPreset p : kEmitterPresets)
        if (presetName(p) == name) return p;
    where.fail("preset", "unknown value \"" + name +
                             "\" (expected \"smoke\", \"steam\", \"vapor_trail\", \"fire\" or \"explosion\")");
}

void readShape(const Json& value, const ParseContext& where, EmitterDesc& d) {
    if (!value.is_object()) where.fail("shape", "must be an object");
    refuseUnknownKeys(value, where, "shape", {"type", "radius", "size"});
    if (value.contains("type")) {
        const std::string type = readString(value["type"], where, "shape.type");
        if (type == "point") d.shape = SpawnShape::Point;
        else if (type == "sphere") d.shape = SpawnShape::Sphere;
        else if (type == "box") d.shape = SpawnShape::Box;
        else if (type == "disc") d.shape = SpawnShape::Disc;
        else where.fail("shape.type", "unknown value \"" + type + "\" (expected \"point\", \"sphere\", \"box\" or \"disc\")");
    }
    const bool round = d.shape == SpawnShape::Sphere || d.shape == SpawnShape::Disc;
    if (value.contains("radius")) {
        if (!round) where.fail("shape.radius", "applies only to shape types \"sphere\" and \"disc\"");
        d.shapeRadius = readNumber(value["radius"], where, "shape.radius", 0.0, kMaxLength, true);
    }
    if (value.contains("size")) {
        if (d.shape != SpawnShape::Box) where.fail("shape.size", "applies only to shape type \"box\"");
        const Json& size = value["size"];
        if (!size.is_array() || size.size() != 3) where.fail("shape.size", "must be an array of 3 numbers");
        for (std::size_t c = 0; c < 3; ++c)
            d.shapeSize[static_cast<int>(c)] = readNumber(size[c], where, element("shape.size", c), 0.0, kMaxLength, true);
    }
}

void readBursts(const Json& value, const ParseContext& where, EmitterDesc& d) {
    if (!value.is_array() || value.size() > kMaxEmitterBursts)
        where.fail("bursts", "must be an array of at most " + std::to_string(kMaxEmitterBursts) + " objects {time, count}");
    d.bursts.clear();
    for (std::size_t i = 0; i < value.size(); ++i) {
        const std::string field = element("bursts", i);
        const Json& b = value[i];
        if (!b.is_object()) where.fail(field, "must be an object {time, count}");
        refuseUnknownKeys(b, where, field, {"time", "count"});
        if (!b.contains("count")) where.fail(field + ".count", "is required");
        EmitterBurst burst;
        if (b.contains("time")) burst.time = readNumber(b["time"], where, field + ".time", 0.0, kMaxTime);
        burst.count = static_cast<std::uint32_t>(readInteger(b["count"], where, field + ".count", 1, kMaxEmitterParticles));
        d.bursts.push_back(burst);
    }
}

void readLifetime(const Json& value, const ParseContext& where, EmitterDesc& d) {
    if (value.is_number()) {
        d.lifetimeMin = d.lifetimeMax = readNumber(value, where, "lifetime", 0.0, kMaxLifetime, true);
        return;
    }
    if (!value.is_array() || value.size() != 2) where.fail("lifetime", "must be a number or an array [min, max] of seconds");
    d.lifetimeMin = readNumber(value[0], where, "lifetime[0]", 0.0, kMaxLifetime, true);
    d.lifetimeMax = readNumber(value[1], where, "lifetime[1]", 0.0, kMaxLifetime, true);
    if (d.lifetimeMax < d.lifetimeMin)
        where.fail("lifetime", "max " + fmt(d.lifetimeMax) + " is less than min " + fmt(d.lifetimeMin));
}

void readTurbulence(const Json& value, const ParseContext& where, EmitterDesc& d) {
    if (!value.is_object()) where.fail("turbulence", "must be an object {strength, scale, speed}");
    refuseUnknownKeys(value, where, "turbulence", {"strength", "scale", "speed"});
    EmitterTurbulence& t = d.turbulence;
    if (value.contains("strength")) t.strength = readNumber(value["strength"], where, "turbulence.strength", 0.0, kMaxCoefficient);
    if (value.contains("scale")) t.scale = readNumber(value["scale"], where, "turbulence.scale", 0.0, 1.0e6, true);
    if (value.contains("speed")) t.speed = readNumber(value["speed"], where, "turbulence.speed", 0.0, kMaxCoefficient);
}

}  // namespace

EmitterDesc parseEmitter(const Json& object, const ParseContext& where) {
    if (!object.is_object()) where.fail("", "must be an object");
    for (auto it = object.begin(); it != object.end(); ++it)
        if (std::find(kEmitterKeys.begin(), kEmitterKeys.end(), it.key()) == kEmitterKeys.end())
            where.fail(it.key(), "unknown key");

    EmitterDesc d = object.contains("preset") ? presetDesc(readPreset(object["preset"], where)) : EmitterDesc{};
    const auto has = [&](const char* key) { return object.contains(key); };
    const auto number = [&](const char* key, double lo, double hi, bool openLow = false) {
        return readNumber(object[key], where, key, lo, hi, openLow);
    };

    if (has("seed")) d.seed = static_cast<std::uint32_t>(readInteger(object["seed"], where, "seed", 0, 0xffffffffu));
    if (has("max_particles"))
        d.maxParticles = static_cast<std::uint32_t>(readInteger(object["max_particles"], where, "max_particles", 1, kMaxEmitterParticles));
    if (has("rate")) d.rate = number("rate", 0.0, kMaxEmitterRate);
    if (has("bursts")) readBursts(object["bursts"], where, d);
    if (has("start")) d.start = number("start", 0.0, kMaxTime);
    if (has("stop")) d.stop = number("stop", 0.0, kMaxTime);
    if (has("lifetime")) readLifetime(object["lifetime"], where, d);
    if (has("shape")) readShape(object["shape"], where, d);
    if (has("velocity")) d.velocity = readVector(object["velocity"], where, "velocity", kMaxSpeed);
    if (has("spread")) d.spread = number("spread", 0.0, kPi);
    if (has("speed_jitter")) d.speedJitter = number("speed_jitter", 0.0, 1.0);
    if (has("inherit_velocity")) d.inheritVelocity = number("inherit_velocity", 0.0, 1.0);
    if (has("radius")) d.radius = readScalarCurve(object["radius"], where, "radius", 0.0, kMaxLength, true);
    if (has("radius_jitter")) {
        d.radiusJitter = number("radius_jitter", 0.0, 1.0);
        if (!(d.radiusJitter < 1.0)) where.fail("radius_jitter", "must be < 1 (a radius must stay > 0)");
    }
    if (has("density")) d.density = readScalarCurve(object["density"], where, "density", 0.0, 1.0e6, false);
    if (has("buoyancy")) d.buoyancy = number("buoyancy", -kMaxCoefficient, kMaxCoefficient);
    if (has("drag")) d.drag = number("drag", 0.0, kMaxCoefficient);
    if (has("wind")) d.wind = readVector(object["wind"], where, "wind", kMaxSpeed);
    if (has("turbulence")) readTurbulence(object["turbulence"], where, d);
    if (has("albedo_over_life")) d.albedoOverLife = readColorCurve(object["albedo_over_life"], where, "albedo_over_life", 1.0);
    if (has("emission_over_life"))
        d.emissionOverLife = readColorCurve(object["emission_over_life"], where, "emission_over_life", 1.0e6);

    // Checks across fields (values may come from the preset or from the file).
    if (!(d.stop > d.start))
        where.fail(has("stop") ? "stop" : "start", "stop (" + fmt(d.stop) + " s) must be later than start (" + fmt(d.start) + " s)");
    for (std::size_t i = 0; i < d.bursts.size(); ++i)
        if (d.bursts[i].count > d.maxParticles)
            where.fail(element("bursts", i) + ".count", std::to_string(d.bursts[i].count) + " is more than max_particles (" +
                                                            std::to_string(d.maxParticles) + ")");
    const double steady = d.rate * d.lifetimeMax;
    if (steady > static_cast<double>(d.maxParticles))
        log::warn(describeInputProblem(where.file, where.object(), where.field,
                                       "rate × lifetime (" + fmt(steady) + ") exceeds max_particles (" +
                                           std::to_string(d.maxParticles) + "): spawns beyond the pool are dropped"));
    return d;
}

}  // namespace nimbus::media
