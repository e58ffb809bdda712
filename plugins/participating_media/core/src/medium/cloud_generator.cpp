#include "nimbus/media/cloud_generator.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "nimbus/media/noise_field.h"

namespace nimbus::media {
namespace {

// SplitMix64: a counter-based stream, so the cloud is the same bits on every machine.
struct Random {
    std::uint64_t state;
    std::uint64_t next() {
        std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }  // [0, 1)
    double between(double a, double b) { return a + (b - a) * uniform(); }
};

struct Ellipsoid {
    glm::dvec3 centre, radii;
};

// The ellipsoids: a main one in the middle and the rest heaped around and above it, each inside `size`.
std::vector<Ellipsoid> placeEllipsoids(const CloudGenerator& g, Random& random) {
    std::vector<Ellipsoid> out;
    const glm::dvec3 half = 0.5 * g.size;
    out.push_back({glm::dvec3(0.0, -0.15 * half.y, 0.0), half * glm::dvec3(0.6, 0.55, 0.6)});
    for (int i = 1; i < g.ellipsoids; ++i) {
        const glm::dvec3 radii = half * glm::dvec3(random.between(0.25, 0.45), random.between(0.3, 0.5), random.between(0.25, 0.45));
        const glm::dvec3 room = glm::max(half - radii, glm::dvec3(0.0));
        const glm::dvec3 centre(random.between(-room.x, room.x), random.between(-0.3 * room.y, room.y), random.between(-room.z, room.z));
        out.push_back({centre, radii});
    }
    return out;
}

GeneratedCloud ellipsoidCloud(const CloudGenerator& g) {
    Random random{g.seed * 0x2545F4914F6CDD1Dull + 1u};
    const std::vector<Ellipsoid> ellipsoids = placeEllipsoids(g, random);
    // Gardner's texture across the cloud: about three cycles of its first octave over the width.
    NoiseField texture{.kind = NoiseKind::Sines, .octaves = 4, .frequency = 3.0 / std::max(g.size.x, g.size.z), .seed = g.seed, .gain = 0.707};
    const NoiseParams params = noiseParams(texture, false);
    GeneratedCloud out;
    const glm::dvec3 half = 0.5 * g.size;
    for (int attempts = 0; static_cast<int>(out.positions.size()) < g.particles && attempts < 64 * g.particles; ++attempts) {
        const glm::dvec3 p(random.between(-half.x, half.x), random.between(-half.y, half.y), random.between(-half.z, half.z));
        double nearestSurface = 2.0;  // the smallest normalised r² over the ellipsoids that hold p
        for (const Ellipsoid& e : ellipsoids) {
            const glm::dvec3 u = (p - e.centre) / e.radii;
            nearestSurface = std::min(nearestSurface, glm::dot(u, u));
        }
        const double radius = random.between(g.radius.x, g.radius.y);
        if (nearestSurface >= 1.0) continue;
        // More transparent towards the surface (Gardner), textured inside.
        const double edge = 1.0 - nearestSurface;
        const double textured = noisePattern(params, glm::vec3(p * texture.frequency));
        out.positions.push_back(glm::vec3(p));
        out.radii.push_back(static_cast<float>(radius));
        out.densities.push_back(static_cast<float>(std::clamp(edge * (0.35 + 1.3 * textured), 0.02, 1.0)));
    }
    return out;
}

// Diamond-square on a (2^6 + 1)² grid that wraps at its edges, each level's displacement in
// [−a, a] with a shrinking by `roughness`; normalised to [0, 1].
std::vector<double> diamondSquare(const CloudGenerator& g, Random& random, int n) {
    const int size = n + 1;
    std::vector<double> h(static_cast<std::size_t>(size * size), 0.0);
    auto at = [&](int x, int z) -> double& { return h[static_cast<std::size_t>(((z % n + n) % n) * size + (x % n + n) % n)]; };
    at(0, 0) = random.between(-1.0, 1.0);
    double amplitude = 1.0;
    for (int step = n; step > 1; step /= 2) {
        const int half = step / 2;
        for (int z = 0; z < n; z += step)  // diamond: each square's centre from its corners
            for (int x = 0; x < n; x += step)
                at(x + half, z + half) = 0.25 * (at(x, z) + at(x + step, z) + at(x, z + step) + at(x + step, z + step)) + amplitude * random.between(-1.0, 1.0);
        for (int z = 0; z < n; z += half)  // square: each edge midpoint from its diamond's corners
            for (int x = (z / half) % 2 == 0 ? half : 0; x < n; x += step)
                at(x, z) = 0.25 * (at(x - half, z) + at(x + half, z) + at(x, z - half) + at(x, z + half)) + amplitude * random.between(-1.0, 1.0);
        amplitude *= g.roughness;
    }
    for (int i = 0; i < size; ++i) {  // the wrapped copies on the last row and column
        h[static_cast<std::size_t>(i * size + n)] = at(0, i);
        h[static_cast<std::size_t>(n * size + i)] = at(i, 0);
    }
    const auto [lo, hi] = std::minmax_element(h.begin(), h.end());
    const double low = *lo, range = std::max(*hi - *lo, 1e-12);
    for (double& v : h) v = (v - low) / range;
    return h;
}

GeneratedCloud diamondSquareCloud(const CloudGenerator& g) {
    constexpr int n = 64;
    Random random{g.seed * 0x2545F4914F6CDD1Dull + 7u};
    const std::vector<double> map = diamondSquare(g, random, n);
    auto value = [&](double u, double v) {  // bilinear over the map, u and v in [0, 1]
        const double x = u * n, z = v * n;
        const int x0 = std::min(static_cast<int>(x), n - 1), z0 = std::min(static_cast<int>(z), n - 1);
        const double fx = x - x0, fz = z - z0;
        auto m = [&](int i, int k) { return map[static_cast<std::size_t>(k * (n + 1) + i)]; };
        return (m(x0, z0) * (1 - fx) + m(x0 + 1, z0) * fx) * (1 - fz) + (m(x0, z0 + 1) * (1 - fx) + m(x0 + 1, z0 + 1) * fx) * fz;
    };
    GeneratedCloud out;
    const glm::dvec3 half = 0.5 * g.size;
    for (int attempts = 0; static_cast<int>(out.positions.size()) < g.particles && attempts < 64 * g.particles; ++attempts) {
        const double u = random.uniform(), v = random.uniform(), up = random.uniform();
        const double radius = random.between(g.radius.x, g.radius.y);
        const double column = (value(u, v) - g.coverage) / (1.0 - g.coverage);  // the column's height share
        if (!(column > 0.0)) continue;
        const double height = up * column * g.size.y;
        out.positions.push_back(glm::vec3(-half.x + u * g.size.x, -half.y + height, -half.z + v * g.size.z));
        out.radii.push_back(static_cast<float>(radius));
        // Denser low in the column, thinning towards its heaped top.
        out.densities.push_back(static_cast<float>(1.0 - 0.6 * up));
    }
    return out;
}

}  // namespace

GeneratedCloud generateCloud(const CloudGenerator& generator) {
    return generator.kind == CloudGeneratorKind::DiamondSquare ? diamondSquareCloud(generator) : ellipsoidCloud(generator);
}

}  // namespace nimbus::media
