#include "raymarch/voxel_grid.h"

#include <algorithm>
#include <cmath>

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
                const std::size_t v = (static_cast<std::size_t>(z) * static_cast<std::size_t>(grid.size.y) + static_cast<std::size_t>(y)) *
                                          static_cast<std::size_t>(grid.size.x) + static_cast<std::size_t>(x);
                grid.scattering[v] += glm::vec4(albedo * s, s);
                grid.emission[v] += glm::vec4(emission * s, g * s);
            }
}

}  // namespace

VoxelGrid voxelize(const ParticleSet& particles, int voxelsAlongLongest) {
    VoxelGrid grid;
    if (particles.empty()) return grid;
    glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
    for (std::size_t i = 0; i < particles.size(); ++i) {
        lo = glm::min(lo, particles.position[i] - static_cast<double>(particles.radius[i]));
        hi = glm::max(hi, particles.position[i] + static_cast<double>(particles.radius[i]));
    }
    const double longest = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z, 1e-6});
    double side = voxelsAlongLongest > 0 ? longest / voxelsAlongLongest : smallRadius(particles) / 3.0;
    if (voxelsAlongLongest <= 0) side = std::max(side, longest / kMaxAutoVoxels);
    grid.voxel = glm::dvec3(side);
    grid.min = lo - side;  // one voxel of padding: trilinear reads fade to 0 at the faces
    grid.size = glm::ivec3(glm::ceil((hi - lo) / side)) + 2;
    const auto count = static_cast<std::size_t>(grid.size.x) * static_cast<std::size_t>(grid.size.y) * static_cast<std::size_t>(grid.size.z);
    grid.scattering.assign(count, glm::vec4(0.0f));
    grid.emission.assign(count, glm::vec4(0.0f));
    grid.rayleigh = std::all_of(particles.phase.begin(), particles.phase.end(), [](PhaseFunction f) { return f == PhaseFunction::Rayleigh; });
    for (std::size_t i = 0; i < particles.size(); ++i) splat(particles, i, grid);
    return grid;
}

}  // namespace nimbus::media
