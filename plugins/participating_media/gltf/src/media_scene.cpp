#include "nimbus/media/media_scene.h"

#include "nimbus/media/emitter_scene.h"

#include "nimbus/media/cloud_generator.h"

#include <algorithm>
#include <cmath>
#include <string_view>

#include "nimbus/base/error.h"
#include "nimbus/base/log.h"

namespace nimbus::media {
namespace {

// Names the place of every problem: file, node, field.
struct Where {
    std::string file;
    std::string node;
    std::string base;  // "extensions.NIMBUS_participating_media"

    [[noreturn]] void fail(std::string_view field, std::string_view problem) const {
        throwInputError(file, node, field.empty() ? base : base + "." + std::string(field), problem);
    }
};

void refuseUnknownKeys(const nlohmann::json& object, std::initializer_list<std::string_view> allowed,
                       const Where& where, const std::string& prefix) {
    for (auto it = object.begin(); it != object.end(); ++it) {
        bool known = false;
        for (std::string_view a : allowed) known = known || it.key() == a;
        if (!known) where.fail(prefix.empty() ? it.key() : prefix + "." + it.key(), "unknown key");
    }
}

double readNumber(const nlohmann::json& value, const Where& where, const std::string& field) {
    if (!value.is_number()) where.fail(field, "must be a number");
    const double v = value.get<double>();
    if (!std::isfinite(v)) where.fail(field, "must be finite");
    return v;
}

glm::vec3 readColor(const nlohmann::json& value, const Where& where, const std::string& field, double lo, double hi,
                    std::string_view range) {
    if (!value.is_array() || value.size() != 3) where.fail(field, "must be an array of 3 numbers");
    glm::vec3 out;
    for (int c = 0; c < 3; ++c) {
        const std::string element = field + "[" + std::to_string(c) + "]";
        const double v = readNumber(value[static_cast<std::size_t>(c)], where, element);
        if (v < lo || v > hi) where.fail(element, "must be " + std::string(range));
        out[c] = static_cast<float>(v);
    }
    return out;
}

Medium parseMedium(const nlohmann::json& object, const Where& where) {
    if (!object.is_object()) where.fail("medium", "must be an object");
    refuseUnknownKeys(object, {"extinction", "albedo", "g", "emission", "phase"}, where, "medium");
    Medium m;
    if (!object.contains("extinction")) where.fail("medium.extinction", "is required");
    const double extinction = readNumber(object["extinction"], where, "medium.extinction");
    if (!(extinction > 0.0) || extinction > 3.0e38) where.fail("medium.extinction", "must be > 0 (and a float)");
    m.extinction = static_cast<float>(extinction);
    if (object.contains("albedo")) m.albedo = readColor(object["albedo"], where, "medium.albedo", 0.0, 1.0, "in [0, 1]");
    if (object.contains("g")) {
        const double g = readNumber(object["g"], where, "medium.g");
        if (!(g > -1.0 && g < 1.0)) where.fail("medium.g", "must be in (-1, 1)");
        m.g = static_cast<float>(g);
    }
    if (object.contains("emission"))
        m.emission = readColor(object["emission"], where, "medium.emission", 0.0, 3.0e38, ">= 0 (and a float)");
    if (object.contains("phase")) {
        const auto& phase = object["phase"];
        if (!phase.is_string()) where.fail("medium.phase", "must be a string");
        const auto name = phase.get<std::string>();
        if (name == "henyey-greenstein") {
            m.phase = PhaseFunction::HenyeyGreenstein;
        } else if (name == "rayleigh") {
            m.phase = PhaseFunction::Rayleigh;
        } else {
            where.fail("medium.phase", "unknown value \"" + name + "\" (expected \"henyey-greenstein\" or \"rayleigh\")");
        }
    }
    return m;
}

int readAccessorIndex(const nlohmann::json& value, const Where& where, const std::string& field) {
    if (!value.is_number_integer() || value.get<long long>() < 0 || value.get<long long>() > 0x7fffffff)
        where.fail(field, "must be an accessor index (an integer >= 0)");
    return static_cast<int>(value.get<long long>());
}

void parseParticles(const GltfDocument& scene, const nlohmann::json& object, const Where& where, MediaNode& out) {
    if (!object.is_object()) where.fail("particles", "must be an object");
    refuseUnknownKeys(object, {"position", "radius", "density"}, where, "particles");
    for (const char* required : {"position", "radius"})
        if (!object.contains(required)) where.fail(std::string("particles.") + required, "is required");

    const std::string full = where.base + ".particles.";
    const int position = readAccessorIndex(object["position"], where, "particles.position");
    const int radius = readAccessorIndex(object["radius"], where, "particles.radius");
    const std::size_t count = scene.accessorCount(position, where.node, full + "position");
    if (count > kMaxParticlesPerNode)
        where.fail("particles.position", std::to_string(count) + " particles is more than the limit of " +
                                             std::to_string(kMaxParticlesPerNode));
    if (scene.accessorCount(radius, where.node, full + "radius") != count)
        where.fail("particles.radius", "count differs from particles.position");
    int density = -1;
    if (object.contains("density")) {
        density = readAccessorIndex(object["density"], where, "particles.density");
        if (scene.accessorCount(density, where.node, full + "density") != count)
            where.fail("particles.density", "count differs from particles.position");
    }

    const std::vector<float> p = scene.readFloats(position, 3, where.node, full + "position");
    out.radii = scene.readFloats(radius, 1, where.node, full + "radius");
    out.densities = density >= 0 ? scene.readFloats(density, 1, where.node, full + "density")
                                 : std::vector<float>(count, 1.0f);
    if (p.size() != 3 * count || out.radii.size() != count || out.densities.size() != count)
        where.fail("particles", "accessor sizes do not match their counts");
    out.localPositions.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
        out.localPositions[i] = {p[3 * i], p[3 * i + 1], p[3 * i + 2]};
        if (!std::isfinite(p[3 * i]) || !std::isfinite(p[3 * i + 1]) || !std::isfinite(p[3 * i + 2]))
            where.fail("particles.position", "element " + std::to_string(i) + " is not finite");
        if (!(out.radii[i] > 0.0f) || !std::isfinite(out.radii[i]))
            where.fail("particles.radius", "element " + std::to_string(i) + " must be > 0 and finite");
        if (!(out.densities[i] >= 0.0f) || !std::isfinite(out.densities[i]))
            where.fail("particles.density", "element " + std::to_string(i) + " must be >= 0 and finite");
        if (!std::isfinite(out.medium.extinction * out.densities[i]))
            where.fail("particles.density", "element " + std::to_string(i) + " times medium.extinction overflows");
    }
}

double readRange(const nlohmann::json& object, const char* key, double fallback, const Where& where, const std::string& field,
                 bool (*ok)(double), std::string_view rule) {
    if (!object.contains(key)) return fallback;
    const double v = readNumber(object[key], where, field);
    if (!ok(v)) where.fail(field, "must be " + std::string(rule) + ", not " + object[key].dump());
    return v;
}

NoiseField parseNoise(const nlohmann::json& object, const Where& where) {
    const std::string base = "volume.noise";
    if (!object.is_object()) where.fail(base, "must be an object");
    refuseUnknownKeys(object, {"kind", "octaves", "frequency", "seed", "gain", "coverage", "falloff", "velocity"}, where, base);
    NoiseField n;
    if (!object.contains("kind")) where.fail(base + ".kind", "is required: \"value\" or \"sines\"");
    const nlohmann::json& kind = object["kind"];
    if (kind == "value") n.kind = NoiseKind::Value;
    else if (kind == "sines") n.kind = NoiseKind::Sines;
    else where.fail(base + ".kind", "unknown kind " + kind.dump() + " (known: \"value\", \"sines\")");
    n.gain = n.kind == NoiseKind::Sines ? 0.707 : 0.5;  // Gardner's 0.707 per octave; fractal noise's usual half
    if (object.contains("octaves")) {
        const nlohmann::json& v = object["octaves"];
        if (!v.is_number_integer() || v.get<long long>() < 1 || v.get<long long>() > kMaxNoiseOctaves)
            where.fail(base + ".octaves", "must be an integer in 1.." + std::to_string(kMaxNoiseOctaves) + ", not " + v.dump());
        n.octaves = static_cast<int>(v.get<long long>());
    }
    if (object.contains("seed")) {
        const nlohmann::json& v = object["seed"];
        if (!v.is_number_integer() || v.get<long long>() < 0 || v.get<long long>() > 0xffffffffLL)
            where.fail(base + ".seed", "must be an integer in 0..4294967295, not " + v.dump());
        n.seed = static_cast<std::uint32_t>(v.get<long long>());
    }
    n.frequency = readRange(object, "frequency", 1.0, where, base + ".frequency", [](double v) { return v > 0.0 && v <= 1e6; }, "> 0 (cycles per metre, at most 1e6)");
    n.gain = readRange(object, "gain", n.gain, where, base + ".gain", [](double v) { return v > 0.0 && v <= 1.0; }, "in (0, 1]");
    n.coverage = readRange(object, "coverage", 0.0, where, base + ".coverage", [](double v) { return v >= 0.0 && v < 1.0; }, "in [0, 1)");
    n.falloff = readRange(object, "falloff", 0.0, where, base + ".falloff", [](double v) { return v >= 0.0 && v <= 1.0; }, "in [0, 1]");
    if (object.contains("velocity")) {
        const nlohmann::json& v = object["velocity"];
        if (!v.is_array() || v.size() != 3) where.fail(base + ".velocity", "must be an array of 3 numbers (m/s)");
        for (int c = 0; c < 3; ++c) {
            const double x = readNumber(v[static_cast<std::size_t>(c)], where, base + ".velocity[" + std::to_string(c) + "]");
            if (std::abs(x) > 1e4) where.fail(base + ".velocity[" + std::to_string(c) + "]", "must be in [-1e4, 1e4] m/s");
            n.velocity[c] = x;
        }
    }
    return n;
}

void parseVolume(const nlohmann::json& object, const Where& where, MediaNode& out) {
    if (!object.is_object()) where.fail("volume", "must be an object");
    refuseUnknownKeys(object, {"shape", "size", "noise"}, where, "volume");
    if (!object.contains("shape")) where.fail("volume.shape", "is required: \"box\" or \"ellipsoid\"");
    const nlohmann::json& shape = object["shape"];
    VolumeDesc desc;
    if (shape == "box") desc.shape = VolumeShape::Box;
    else if (shape == "ellipsoid") desc.shape = VolumeShape::Ellipsoid;
    else where.fail("volume.shape", "unknown shape " + shape.dump() + " (known: \"box\", \"ellipsoid\")");
    if (!object.contains("size")) where.fail("volume.size", "is required: [x, y, z] in metres");
    const nlohmann::json& size = object["size"];
    if (!size.is_array() || size.size() != 3) where.fail("volume.size", "must be an array of 3 numbers");
    for (int c = 0; c < 3; ++c) {
        const std::string element = "volume.size[" + std::to_string(c) + "]";
        const double v = readNumber(size[static_cast<std::size_t>(c)], where, element);
        if (!(v > 0.0) || v > 1e12) where.fail(element, "must be > 0 (and at most 1e12 m), not " + size[static_cast<std::size_t>(c)].dump());
        desc.size[c] = v;
    }
    if (object.contains("noise")) desc.noise = parseNoise(object["noise"], where);
    out.volume = desc;
}

// A `generator` object: its particles, made now (they are static, like `particles`).
void parseGenerator(const nlohmann::json& object, const Where& where, MediaNode& out) {
    const std::string base = "generator";
    if (!object.is_object()) where.fail(base, "must be an object");
    refuseUnknownKeys(object, {"kind", "seed", "particles", "size", "radius", "ellipsoids", "roughness", "coverage"}, where, base);
    CloudGenerator g;
    if (!object.contains("kind")) where.fail(base + ".kind", "is required: \"ellipsoids\" or \"diamond-square\"");
    const nlohmann::json& kind = object["kind"];
    if (kind == "ellipsoids") g.kind = CloudGeneratorKind::Ellipsoids;
    else if (kind == "diamond-square") g.kind = CloudGeneratorKind::DiamondSquare;
    else where.fail(base + ".kind", "unknown kind " + kind.dump() + " (known: \"ellipsoids\", \"diamond-square\")");
    auto integer = [&](const char* key, long long lo, long long hi, long long fallback) {
        if (!object.contains(key)) return fallback;
        const nlohmann::json& v = object[key];
        if (!v.is_number_integer() || v.get<long long>() < lo || v.get<long long>() > hi)
            where.fail(base + "." + key, "must be an integer in " + std::to_string(lo) + ".." + std::to_string(hi) + ", not " + v.dump());
        return v.get<long long>();
    };
    g.seed = static_cast<std::uint32_t>(integer("seed", 0, 0xffffffffLL, 0));
    g.particles = static_cast<int>(integer("particles", 1, kMaxGeneratedParticles, g.particles));
    g.ellipsoids = static_cast<int>(integer("ellipsoids", 1, 64, g.ellipsoids));
    if (!object.contains("size")) where.fail(base + ".size", "is required: [x, y, z] in metres");
    const nlohmann::json& size = object["size"];
    if (!size.is_array() || size.size() != 3) where.fail(base + ".size", "must be an array of 3 numbers");
    for (int c = 0; c < 3; ++c) {
        const std::string field = base + ".size[" + std::to_string(c) + "]";
        const double v = readNumber(size[static_cast<std::size_t>(c)], where, field);
        if (!(v > 0.0) || v > 1e6) where.fail(field, "must be > 0 (and at most 1e6 m)");
        g.size[c] = v;
    }
    if (object.contains("radius")) {
        const nlohmann::json& r = object["radius"];
        if (!r.is_array() || r.size() != 2) where.fail(base + ".radius", "must be [min, max] in metres");
        const double lo = readNumber(r[0], where, base + ".radius[0]"), hi = readNumber(r[1], where, base + ".radius[1]");
        if (!(lo > 0.0) || !(hi >= lo) || hi > 1e6) where.fail(base + ".radius", "must be 0 < min <= max (at most 1e6 m)");
        g.radius = {lo, hi};
    }
    g.roughness = readRange(object, "roughness", g.roughness, where, base + ".roughness", [](double v) { return v > 0.0 && v < 1.0; }, "in (0, 1)");
    g.coverage = readRange(object, "coverage", g.coverage, where, base + ".coverage", [](double v) { return v >= 0.0 && v < 1.0; }, "in [0, 1)");
    GeneratedCloud cloud = generateCloud(g);
    out.localPositions = std::move(cloud.positions);
    out.radii = std::move(cloud.radii);
    out.densities = std::move(cloud.densities);
}

}  // namespace

MediaScene parseMediaScene(const GltfDocument& scene) {
    MediaScene media;
    const std::string file = scene.displayName();
    for (std::size_t n = 0; n < scene.nodeCount(); ++n) {
        const nlohmann::json* extension = scene.mediaExtension(n);
        if (extension == nullptr) continue;
        const std::string name = scene.nodeName(n);
        // Same object naming as the asset loader: node "name" (nodes[n]).
        const std::string index = "nodes[" + std::to_string(n) + "]";
        Where where{file, name.empty() ? index : "node \"" + name + "\" (" + index + ")", std::string("extensions.") + kMediaExtension};
        const nlohmann::json& object = *extension;
        if (!object.is_object()) where.fail("", "must be an object");
        refuseUnknownKeys(object, {"medium", "particles", "generator", "volume", "emitter", "render"}, where, "");
        if (!object.contains("medium")) where.fail("medium", "is required");

        MediaNode out;
        out.node = static_cast<int>(n);
        out.name = name;
        out.origin = file + ": " + where.node;
        out.medium = parseMedium(object["medium"], where);
        if (object.contains("particles")) parseParticles(scene, object["particles"], where, out);
        if (object.contains("generator")) {
            if (object.contains("particles")) where.fail("generator", "cannot stand beside particles on one node (each makes the node's static cloud)");
            parseGenerator(object["generator"], where, out);
        }
        if (object.contains("volume")) parseVolume(object["volume"], where, out);
        if (object.contains("emitter")) out.emitter = object["emitter"];
        if (object.contains("render")) out.render = object["render"];
        if (!out.emitter.is_null()) (void)parseNodeEmitter(scene, out);  // refuse a bad emitter at load, not mid-run
        media.nodes.push_back(std::move(out));
    }
    return media;
}

void appendCloudParticles(ParticleSet& out, const Medium& medium, const std::vector<glm::vec3>& positions,
                          const std::vector<float>& radii, const std::vector<float>& densities, const glm::dmat4& world) {
    const double scale = std::cbrt(std::abs(glm::determinant(glm::dmat3(world))));
    for (std::size_t i = 0; i < positions.size(); ++i) {
        const float density = densities.empty() ? 1.0f : densities[i];
        if (!(density > 0.0f)) continue;  // no extinction: invisible, and nothing to shadow
        const glm::dvec3 p = glm::dvec3(world * glm::dvec4(glm::dvec3(positions[i]), 1.0));
        out.push(p, static_cast<float>(radii[i] * scale), static_cast<float>(static_cast<double>(medium.extinction) * density), medium);
    }
}

bool hasUniformScale(const glm::dmat4& world) {
    const glm::dmat3 linear(world);
    // A sphere stays a sphere only under a uniform scale: compare the column lengths.
    const double sx = glm::length(linear[0]), sy = glm::length(linear[1]), sz = glm::length(linear[2]);
    return std::max({sx, sy, sz}) <= (1.0 + 1e-6) * std::min({sx, sy, sz});
}

ParticleSet staticParticles(const MediaScene& media, const std::vector<glm::dmat4>& world) {
    ParticleSet set;
    std::size_t total = 0;
    for (const MediaNode& n : media.nodes) total += n.localPositions.size();
    set.reserve(total);
    for (const MediaNode& n : media.nodes) {
        if (n.localPositions.empty()) continue;
        const glm::dmat4 m = n.node >= 0 && static_cast<std::size_t>(n.node) < world.size()
                                 ? world[static_cast<std::size_t>(n.node)]
                                 : glm::dmat4(1.0);
        if (!hasUniformScale(m))
            log::warn("nodes[" + std::to_string(n.node) + "] \"" + n.name +
                      "\": non-uniform scale on a particle cloud; radii use the mean scale cbrt|det|");
        appendCloudParticles(set, n.medium, n.localPositions, n.radii, n.densities, m);
    }
    return set;
}

std::vector<Volume> sceneVolumes(const MediaScene& media, const std::vector<glm::dmat4>& world, double time) {
    std::vector<Volume> out;
    for (const MediaNode& n : media.nodes) {
        if (!n.volume) continue;
        const glm::dmat4 m = n.node >= 0 && static_cast<std::size_t>(n.node) < world.size() ? world[static_cast<std::size_t>(n.node)]
                                                                                            : glm::dmat4(1.0);
        out.push_back(makeVolume(*n.volume, m, n.medium, n.origin, time));
    }
    return out;
}

ParticleSet particlesAtTime(const GltfDocument& scene, const MediaScene& media, double timeSeconds) {
    ParticleSet set = staticParticles(media, scene.worldTransforms(timeSeconds));
    set.append(simulateEmittersTo(scene, media, timeSeconds));
    return set;
}

}  // namespace nimbus::media
