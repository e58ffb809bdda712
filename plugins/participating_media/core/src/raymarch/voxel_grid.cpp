#include "raymarch/voxel_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "nimbus/media/medium_footprint.h"

namespace nimbus::media {
namespace {

constexpr double kKernel = 4.5;  // ρ(r) = exp(−4.5 r²/R²), r < R (optics.h)

// The small particles set the grid: a fire's small flames among large smoke puffs would blur at
// the mean size. The 10th percentile ignores a few stray tiny ones.
double smallRadius(const ParticleSet& particles) {
    std::vector<float> radii = particles.radius;
    const auto at = radii.begin() + static_cast<std::ptrdiff_t>(radii.size() / 10);
    std::nth_element(radii.begin(), at, radii.end());
    return *at;
}

std::size_t voxelIndex(const VoxelGrid& grid, int x, int y, int z) {
    return (static_cast<std::size_t>(z) * static_cast<std::size_t>(grid.size.y) + static_cast<std::size_t>(y)) *
               static_cast<std::size_t>(grid.size.x) + static_cast<std::size_t>(x);
}

// Adds particle i's kernel to every voxel centre inside its sphere.
void splat(const ParticleSet& p, std::size_t i, VoxelGrid& grid) {
    const double radius = p.radius[i];
    if (!(radius > 0.0) || !(p.sigma[i] > 0.0f)) return;
    const glm::dvec3 local = (p.position[i] - grid.min) / grid.voxel - 0.5;  // in voxel-centre units
    const glm::dvec3 reach = glm::dvec3(radius) / grid.voxel;
    const glm::ivec3 lo = glm::max(glm::ivec3(glm::ceil(local - reach)), glm::ivec3(0));
    const glm::ivec3 hi = glm::min(glm::ivec3(glm::floor(local + reach)), grid.size - 1);
    const double sigma = p.sigma[i], invR2 = 1.0 / (radius * radius);
    const glm::vec3 albedo = p.albedo[i], emission = p.emission[i];
    const float g = p.g[i];
    for (int z = lo.z; z <= hi.z; ++z)
        for (int y = lo.y; y <= hi.y; ++y)
            for (int x = lo.x; x <= hi.x; ++x) {
                const glm::dvec3 d = (glm::dvec3(x, y, z) - local) * grid.voxel;
                const double r2 = glm::dot(d, d) * invR2;
                if (r2 >= 1.0) continue;
                const auto s = static_cast<float>(sigma * std::exp(-kKernel * r2));
                const std::size_t v = voxelIndex(grid, x, y, z);
                grid.scattering[v] += glm::vec4(albedo * s, s);
                grid.emission[v] += glm::vec4(emission * s, g * s);
            }
}

// The share of the voxel with centre `centre` and side `side` inside the volume: 1 or 0 where all
// eight corners agree (both shapes are convex, so a voxel with every corner inside is inside),
// else the share of kCoverageSamples³ sub-sample centres inside.
double coverage(const Volume& volume, const glm::dvec3& centre, double side) {
    int inside = 0;
    for (int c = 0; c < 8; ++c)
        inside += volumeContains(volume, centre + 0.5 * side * glm::dvec3(c & 1 ? 1 : -1, c & 2 ? 1 : -1, c & 4 ? 1 : -1)) ? 1 : 0;
    if (inside == 8) return 1.0;
    constexpr int n = kCoverageSamples;
    int hits = 0;
    for (int k = 0; k < n * n * n; ++k) {
        const glm::dvec3 sub(k % n, (k / n) % n, k / (n * n));
        hits += volumeContains(volume, centre + side * ((sub + 0.5) / double(n) - 0.5)) ? 1 : 0;
    }
    return hits / double(n * n * n);
}

// Adds a volume's constant medium, weighted by coverage, to every voxel it reaches.
void fillVolume(const Volume& volume, VoxelGrid& grid) {
    const Aabb box = volumeBounds(volume);
    const glm::ivec3 lo = glm::max(glm::ivec3(glm::floor((box.min - grid.min) / grid.voxel)), glm::ivec3(0));
    const glm::ivec3 hi = glm::min(glm::ivec3(glm::floor((box.max - grid.min) / grid.voxel)), grid.size - 1);
    const double sigma = volume.sigma();
    const Medium& m = volume.medium;
    for (int z = lo.z; z <= hi.z; ++z)
        for (int y = lo.y; y <= hi.y; ++y)
            for (int x = lo.x; x <= hi.x; ++x) {
                const double share = coverage(volume, grid.min + (glm::dvec3(x, y, z) + 0.5) * grid.voxel, grid.voxel.x);
                if (!(share > 0.0)) continue;
                const auto s = static_cast<float>(sigma * share);
                const std::size_t v = voxelIndex(grid, x, y, z);
                grid.scattering[v] += glm::vec4(m.albedo * s, s);
                grid.emission[v] += glm::vec4(m.emission * s, m.g * s);
            }
}

// The voxel side when none is asked (kMaxAutoVoxels above): a volume's faces are sharp at any
// size, so a scene with one takes the finest grid.
double automaticSide(const ParticleSet& particles, const std::vector<Volume>& volumes, double longest) {
    const double side = particles.empty() || !volumes.empty() ? 0.0 : smallRadius(particles) / 3.0;
    return std::max(side, longest / kMaxAutoVoxels);
}

}  // namespace

VoxelGrid voxelize(const ParticleSet& particles, const std::vector<Volume>& volumes, int voxelsAlongLongest) {
    VoxelGrid grid;
    if (particles.empty() && volumes.empty()) return grid;
    const Aabb bounds = [&] {
        Aabb b = particleBounds(particles);
        b.extend(volumeBounds(volumes));
        return b;
    }();
    const glm::dvec3 lo = bounds.min, hi = bounds.max;
    const double longest = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z, 1e-6});
    const double side = voxelsAlongLongest > 0 ? longest / voxelsAlongLongest : automaticSide(particles, volumes, longest);
    grid.voxel = glm::dvec3(side);
    grid.min = lo - side;  // one voxel of padding: trilinear reads fade to 0 at the faces
    grid.size = glm::ivec3(glm::ceil((hi - lo) / side)) + 2;
    const auto count = static_cast<std::size_t>(grid.size.x) * static_cast<std::size_t>(grid.size.y) * static_cast<std::size_t>(grid.size.z);
    grid.scattering.assign(count, glm::vec4(0.0f));
    grid.emission.assign(count, glm::vec4(0.0f));
    grid.rayleigh = std::all_of(particles.phase.begin(), particles.phase.end(), [](PhaseFunction f) { return f == PhaseFunction::Rayleigh; }) &&
                    std::all_of(volumes.begin(), volumes.end(), [](const Volume& v) { return v.medium.phase == PhaseFunction::Rayleigh; });
    for (std::size_t i = 0; i < particles.size(); ++i) splat(particles, i, grid);
    for (const Volume& v : volumes)
        if (!v.noise) fillVolume(v, grid);  // noise volumes are evaluated on the GPU (raymarch_noise_pass.h)
    return grid;
}

}  // namespace nimbus::media
