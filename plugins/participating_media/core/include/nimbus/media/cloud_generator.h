#pragma once
// Seeded generators that fill a cloud with particles (a node's `generator` object,
// docs/scene-format.md §3.7), after Gardner's textured ellipsoids and Fournier, Fussell and
// Carpenter's diamond-square midpoint displacement as the OpenGL course notes on natural phenomena
// describe them:
//   ellipsoids      a few ellipsoids placed by the seed inside `size`; particles uniform in their
//                   union, each particle's density Gardner's sums-of-sines texture times a
//                   transparency that grows towards the ellipsoid's surface;
//   diamond-square  a midpoint-displacement height map over the footprint (x, z), 65 × 65 values;
//                   particles fill each column from the base up to a height that follows the map
//                   above `coverage`: a cloud layer with a flat base and a heaped top.
// The same inputs give the same particles on every machine (a counter-based generator, no
// library distributions).
//
// Does not: move particles over time (a generated cloud is static, like `particles`), or read JSON.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace nimbus::media {

enum class CloudGeneratorKind : std::uint8_t { Ellipsoids, DiamondSquare };

inline constexpr int kMaxGeneratedParticles = 1 << 20;

struct CloudGenerator {
    CloudGeneratorKind kind = CloudGeneratorKind::Ellipsoids;
    std::uint32_t seed = 0;
    int particles = 1000;             // 1..kMaxGeneratedParticles
    glm::dvec3 size{10.0, 5.0, 10.0}; // the cloud's extents in the node's frame, centred on it (m)
    glm::dvec2 radius{0.4, 0.8};      // particle radii, uniform in [min, max] (m)
    int ellipsoids = 5;               // ellipsoids: how many (1..64)
    double roughness = 0.55;          // diamond-square: each level's displacement over the last's, (0, 1)
    double coverage = 0.35;           // diamond-square: the map value below which a column is clear, [0, 1)
};

struct GeneratedCloud {
    std::vector<glm::vec3> positions;  // node frame
    std::vector<float> radii, densities;
};

GeneratedCloud generateCloud(const CloudGenerator& generator);

}  // namespace nimbus::media
