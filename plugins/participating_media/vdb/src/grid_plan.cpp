#include "nimbus/media/vdb/grid_plan.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace nimbus::media::vdb {
namespace {

constexpr double kPi = 3.14159265358979323846;
// Cells per side of the coarse occupancy map that bounds the union of the particles' spheres.
constexpr int kOccupancyCells = 64;

Aabb mediumBounds(const ParticleSet& particles, const std::vector<Volume>& volumes) {
    Aabb b;
    for (std::size_t i = 0; i < particles.size(); ++i) {
        b.extend(particles.position[i] - static_cast<double>(particles.radius[i]));
        b.extend(particles.position[i] + static_cast<double>(particles.radius[i]));
    }
    b.extend(volumeBounds(volumes));
    return b;
}

// The 10th percentile of the radii: a fire's small flames among large smoke puffs set the voxel,
// a few stray tiny ones do not.
double smallRadius(const ParticleSet& particles) {
    std::vector<float> radii = particles.radius;
    const auto at = radii.begin() + static_cast<std::ptrdiff_t>(radii.size() / 10);
    std::nth_element(radii.begin(), at, radii.end());
    return *at;
}

// An upper bound of how much a world length shrinks into the node's frame (the Frobenius norm
// of the world-to-node map bounds its largest stretch).
double toLocalStretch(const Volume& v) {
    const glm::dmat3 m(v.toLocal);
    return std::sqrt(glm::dot(m[0], m[0]) + glm::dot(m[1], m[1]) + glm::dot(m[2], m[2]));
}

double volumeVoxel(const Volume& v) {
    const glm::dmat3 m(v.world);
    double thinnest = std::numeric_limits<double>::infinity();
    for (int a = 0; a < 3; ++a) thinnest = std::min(thinnest, glm::length(m[a]) * v.size[a]);
    double side = thinnest / kVolumeVoxelsAcross;
    if (v.noise) {
        const double ratio = v.noise->kind == NoiseKind::Sines ? 1.5 : 1.0;  // the sines' axis ratios mₐ < 1.5
        const double finest = v.noise->frequency * std::ldexp(1.0, v.noise->octaves - 1) * ratio;  // cycles per node metre
        side = std::min(side, 1.0 / (finest * toLocalStretch(v)) / kNoiseVoxelsPerWavelength);
    }
    return side;
}

double automaticVoxel(const ParticleSet& particles, const std::vector<Volume>& volumes) {
    double side = particles.empty() ? std::numeric_limits<double>::infinity() : smallRadius(particles) / kParticleVoxelsPerRadius;
    for (const Volume& v : volumes) side = std::min(side, volumeVoxel(v));
    return side;
}

// Voxel centres in [lo, hi] along one axis at side h.
double centresAlong(double lo, double hi, double h) { return std::max(0.0, std::floor(hi / h) - std::ceil(lo / h) + 1.0); }

double boxCentres(const Aabb& b, double h) {
    return centresAlong(b.min.x, b.max.x, h) * centresAlong(b.min.y, b.max.y, h) * centresAlong(b.min.z, b.max.z, h);
}

// Upper bounds of the active voxels at any side h, from three views of the medium: the sum of
// each particle's sphere and each volume's box (overlaps counted twice), the coarse cells that
// the medium touches, and the whole box. The least of them is the estimate.
class VoxelEstimate {
public:
    VoxelEstimate(const ParticleSet& particles, const std::vector<Volume>& volumes, const Aabb& bounds)
        : particles_(particles), volumes_(volumes), bounds_(bounds) {
        const glm::dvec3 extent = bounds.extent();
        cell_ = std::max({extent.x, extent.y, extent.z, 1e-9}) / kOccupancyCells;
        std::vector<char> touched(static_cast<std::size_t>(kOccupancyCells + 1) * (kOccupancyCells + 1) * (kOccupancyCells + 1), 0);
        auto mark = [&](const Aabb& box) {
            const glm::ivec3 lo = cellOf(box.min), hi = cellOf(box.max);
            for (int z = lo.z; z <= hi.z; ++z)
                for (int y = lo.y; y <= hi.y; ++y)
                    for (int x = lo.x; x <= hi.x; ++x)
                        touched[(static_cast<std::size_t>(z) * (kOccupancyCells + 1) + static_cast<std::size_t>(y)) * (kOccupancyCells + 1) +
                                static_cast<std::size_t>(x)] = 1;
        };
        for (std::size_t i = 0; i < particles.size(); ++i) {
            const double r = particles.radius[i];
            mark(Aabb{particles.position[i] - r, particles.position[i] + r});
        }
        for (const Volume& v : volumes) mark(volumeBounds(v));
        touchedCells_ = static_cast<double>(std::count(touched.begin(), touched.end(), char{1}));
    }

    double operator()(double h) const {
        double sum = 0.0;
        for (float r : particles_.radius) {
            const double reach = r / h + 0.8660254037844386;  // centres whose voxel meets the sphere lie within R + √3h/2
            sum += 4.0 / 3.0 * kPi * reach * reach * reach;
        }
        for (const Volume& v : volumes_) sum += boxCentres(volumeBounds(v), h);
        const double perCell = cell_ / h + 1.0;
        return std::min({sum, touchedCells_ * perCell * perCell * perCell, boxCentres(bounds_, h)});
    }

private:
    glm::ivec3 cellOf(const glm::dvec3& p) const {
        return glm::clamp(glm::ivec3(glm::floor((p - bounds_.min) / cell_)), glm::ivec3(0), glm::ivec3(kOccupancyCells));
    }

    const ParticleSet& particles_;
    const std::vector<Volume>& volumes_;
    Aabb bounds_;
    double cell_ = 1.0;
    double touchedCells_ = 0.0;
};

bool indexFits(const Aabb& b, double h) {
    const double far = std::max(glm::length(glm::max(glm::abs(b.min), glm::abs(b.max))), 0.0);
    return far / h < kMaxIndex;
}

// The smallest side at which the medium fits `limit` voxels and the 32-bit index range: bisection
// in log space (the estimate falls as the side grows).
double smallestFitting(const VoxelEstimate& estimate, const Aabb& bounds, double limit) {
    const glm::dvec3 extent = bounds.extent();
    double hi = std::max({extent.x, extent.y, extent.z, 1e-9}) * 2.0;
    double lo = hi * 1e-12;
    auto fits = [&](double h) { return estimate(h) <= limit && indexFits(bounds, h); };
    while (!fits(hi)) hi *= 2.0;  // a medium far from the origin may need more than its size
    for (int i = 0; i < 80; ++i) {
        const double mid = std::sqrt(lo * hi);
        (fits(mid) ? hi : lo) = mid;
    }
    return hi;
}

}  // namespace

GridPlan planGrid(const ParticleSet& particles, const std::vector<Volume>& volumes, double voxel, double limit) {
    GridPlan plan;
    if (particles.empty() && volumes.empty()) return plan;
    plan.bounds = mediumBounds(particles, volumes);
    const VoxelEstimate estimate(particles, volumes, plan.bounds);
    plan.automatic = !(voxel > 0.0);
    if (plan.automatic) limit = std::min(limit, kAutoVoxels);
    plan.smallestVoxel = smallestFitting(estimate, plan.bounds, limit);
    plan.voxel = plan.automatic ? automaticVoxel(particles, volumes) : voxel;
    if (plan.automatic && plan.voxel < plan.smallestVoxel) {
        plan.voxel = plan.smallestVoxel;
        plan.coarsened = true;
    }
    const double h = plan.voxel;
    plan.estimatedVoxels = estimate(h);
    plan.boxVoxels = boxCentres(plan.bounds, h);
    plan.fits = plan.estimatedVoxels <= limit && indexFits(plan.bounds, h);
    if (plan.fits) {
        plan.indexMin = glm::ivec3(glm::ceil(plan.bounds.min / h));
        plan.indexMax = glm::ivec3(glm::floor(plan.bounds.max / h));
    }
    return plan;
}

double kernelError(double voxel, double radius) { return -std::expm1(-9.0 * voxel * voxel / (4.0 * radius * radius)); }

}  // namespace nimbus::media::vdb
