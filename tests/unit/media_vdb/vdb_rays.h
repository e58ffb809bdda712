#pragma once
// Test helper: optical depth along a ray through an exported density grid, read as a path tracer
// reads it: world → index through the grid's own transform, trilinear interpolation between voxel
// centres (OpenVDB's BoxSampler). Within each cell between centre planes the interpolant is a
// cubic along the ray, so two-point Gauss–Legendre per cell integrates it exactly: what is left
// of a difference from the closed form is the grid's, not this helper's.
#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/glm.hpp>
#include <openvdb/openvdb.h>
#include <openvdb/tools/Interpolation.h>

#include "nimbus/media/optics.h"
#include "nimbus/media/particle_set.h"
#include "nimbus/media/vdb/grid_plan.h"
#include "nimbus/media/volume.h"

namespace nimbus::media::test {

// ∫ density over origin + t·dir, t in [t0, t1] (dir unit length, metres).
inline double gridOpticalDepth(const openvdb::FloatGrid& grid, const glm::dvec3& origin, const glm::dvec3& dir, double t0, double t1) {
    const openvdb::math::Transform& xf = grid.transform();
    const openvdb::Vec3d o = xf.worldToIndex(openvdb::Vec3d(origin.x, origin.y, origin.z));
    const openvdb::Vec3d d = xf.worldToIndex(openvdb::Vec3d(origin.x + dir.x, origin.y + dir.y, origin.z + dir.z)) - o;
    std::vector<double> cuts{t0, t1};
    for (int a = 0; a < 3; ++a) {
        if (d[a] == 0.0) continue;
        const double from = std::min(o[a] + t0 * d[a], o[a] + t1 * d[a]), to = std::max(o[a] + t0 * d[a], o[a] + t1 * d[a]);
        for (double k = std::ceil(from); k <= to; k += 1.0) cuts.push_back((k - o[a]) / d[a]);
    }
    std::sort(cuts.begin(), cuts.end());
    const openvdb::tools::GridSampler<openvdb::FloatGrid, openvdb::tools::BoxSampler> sampler(grid);
    constexpr double kNode = 0.5773502691896257;  // 1/√3
    double sum = 0.0;
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
        const double a = std::max(cuts[i], t0), b = std::min(cuts[i + 1], t1);
        if (!(b > a)) continue;
        const double mid = 0.5 * (a + b), half = 0.5 * (b - a);
        for (double s : {-kNode, kNode}) sum += half * sampler.isSample(o + d * (mid + s * half));
    }
    return sum;
}

// The closed form of the same: each particle's erf form plus each volume's σ × chord (constant
// volumes only).
inline double closedFormOpticalDepth(const ParticleSet& particles, const std::vector<Volume>& volumes, const glm::dvec3& origin,
                                     const glm::dvec3& dir, double t0, double t1) {
    double tau = 0.0;
    for (std::size_t i = 0; i < particles.size(); ++i)
        tau += particleOpticalDepth(chordGeometry(origin, dir, particles.position[i], particles.radius[i]), particles.sigma[i],
                                    particles.radius[i], t0, t1);
    for (const Volume& v : volumes) tau += volumeOpticalDepth(v, origin, dir, t0, t1);
    return tau;
}

// The length of the ray's line within distance `margin` of the particle's sphere surface.
inline double sphereShellLength(const glm::dvec3& origin, const glm::dvec3& dir, const glm::dvec3& centre, double radius, double margin) {
    auto chord = [&](double r) { return r > 0.0 ? 2.0 * chordGeometry(origin, dir, centre, r).halfChord : 0.0; };
    return chord(radius + margin) - chord(radius - margin);
}

// The same for a volume's surface: the chord through the shape grown by `margin` less the chord
// through it shrunk by as much. A world ball of radius m lies within a node-frame ball of m times
// the world-to-node map's Frobenius norm; a box grows by that along each axis, an ellipsoid by
// scaling (E ⊕ B(m) ⊆ (1 + m/a_min) E for a convex E).
inline double volumeShellLength(const Volume& v, const glm::dvec3& origin, const glm::dvec3& dir, double margin) {
    const glm::dmat3 m(v.toLocal);
    const double local = margin * std::sqrt(glm::dot(m[0], m[0]) + glm::dot(m[1], m[1]) + glm::dot(m[2], m[2]));
    auto chord = [&](double grow) {
        glm::dvec3 size = v.size;
        if (v.shape == VolumeShape::Box) size += 2.0 * grow;
        else size *= 1.0 + 2.0 * grow / std::min({v.size.x, v.size.y, v.size.z});
        if (!(std::min({size.x, size.y, size.z}) > 0.0)) return 0.0;
        const VolumeChord c = volumeChord(makeVolume(v.shape, v.world, size, v.medium), origin, dir);
        return c.hit() ? c.exit - c.enter : 0.0;
    };
    return chord(local) - chord(-local);
}

// The stated error of one ray through a grid of side h (docs/export.md), a sum over what it meets:
// - a particle: kernelError × its centre depth (the Gaussian's flattening by trilinear reads),
//   plus its truncation step σe^(−4.5) over the ray's length within √3h of its sphere (a read
//   takes the centres up to √3h away, so the step is smeared over that shell and nowhere else);
// - a constant volume: σ over the ray's length within (3√3/2)h of its surface (a centre's value
//   differs from the medium there only when its voxel, half-diagonal √3h/2, meets the surface).
inline double statedOpticalDepthError(const ParticleSet& particles, const std::vector<Volume>& volumes, double h, const glm::dvec3& origin,
                                      const glm::dvec3& dir) {
    constexpr double kRoot3 = 1.7320508075688772;
    double bound = 0.0;
    for (std::size_t i = 0; i < particles.size(); ++i) {
        const double r = particles.radius[i], sigma = particles.sigma[i];
        if (!chordGeometry(origin, dir, particles.position[i], r + kRoot3 * h).hit()) continue;
        bound += vdb::kernelError(h, r) * particleOpticalDepth(sigma, r, 0.0, -r, r) +
                 sigma * std::exp(-kKernelFalloff) * sphereShellLength(origin, dir, particles.position[i], r, kRoot3 * h);
    }
    for (const Volume& v : volumes)
        if (!v.noise) bound += v.sigma() * volumeShellLength(v, origin, dir, 1.5 * kRoot3 * h);
    return bound;
}

}  // namespace nimbus::media::test
