#include "common/environment_grid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "common/grid_slabs.h"
#include "common/voxel_light.h"
#include "nimbus/media/optics.h"

namespace nimbus::media {
namespace {

// ∫ σ ρ dV of one particle over its sphere: 4π σ ∫₀^R r² e^{−k r²} dr, k = 4.5/R².
double opticalVolume(double sigma, double radius) {
    const double k = kKernelFalloff / (radius * radius), sk = std::sqrt(k);
    return sigma * (std::pow(kPi / k, 1.5) * std::erf(sk * radius) - 2.0 * kPi * radius / k * std::exp(-k * radius * radius));
}

void splatParticle(const ParticleSet& p, std::size_t i, MediumGrid& m) {
    const double radius = p.radius[i];
    if (!(radius > 0.0) || !(p.sigma[i] > 0.0f)) return;
    const glm::dvec3 local = (p.position[i] - m.min) / m.voxel - 0.5;  // in voxel-centre units
    const double reach = radius / m.voxel;
    const glm::ivec3 lo = glm::max(glm::ivec3(glm::ceil(local - reach)), glm::ivec3(0));
    const glm::ivec3 hi = glm::min(glm::ivec3(glm::floor(local + reach)), m.size - 1);
    const double target = opticalVolume(p.sigma[i], radius) / (m.voxel * m.voxel * m.voxel);  // the sum over voxels it should make
    const double invR2 = 1.0 / (radius * radius);
    auto weight = [&](int x, int y, int z) {
        const glm::dvec3 d = (glm::dvec3(x, y, z) - local) * m.voxel;
        const double r2 = glm::dot(d, d) * invR2;
        return r2 < 1.0 ? std::exp(-kKernelFalloff * r2) : 0.0;
    };
    auto add = [&](std::size_t v, double sigma) {
        m.sigma[v] += static_cast<float>(sigma);
        m.scattering[v] += static_cast<float>(sigma) * p.albedo[i];
        m.sigmaG[v] += static_cast<float>(sigma) * p.g[i];
        m.emission[v] += static_cast<float>(sigma) * p.emission[i];
    };
    double sum = 0.0;
    for (int z = lo.z; z <= hi.z; ++z)
        for (int y = lo.y; y <= hi.y; ++y)
            for (int x = lo.x; x <= hi.x; ++x) sum += weight(x, y, z);
    if (!(sum > 0.0)) {  // smaller than a voxel: all of it on the nearest centre
        const glm::ivec3 c = glm::clamp(glm::ivec3(glm::round(local)), glm::ivec3(0), m.size - 1);
        add(m.index(c.x, c.y, c.z), target);
        return;
    }
    const double scale = target / sum;
    for (int z = lo.z; z <= hi.z; ++z)
        for (int y = lo.y; y <= hi.y; ++y)
            for (int x = lo.x; x <= hi.x; ++x) add(m.index(x, y, z), scale * weight(x, y, z));
}

// Optical depth from every voxel centre to the grid's edge along step s (a lattice direction),
// trapezoid rule along the lattice line; the lines are swept from the edge they leave by.
std::vector<float> sweep(const MediumGrid& m, const glm::ivec3& s) {
    const std::vector<float>& sigma = m.sigma;
    const glm::ivec3& size = m.size;
    const double voxel = m.voxel;
    std::vector<float> tau(sigma.size(), 0.0f);
    const double step = voxel * glm::length(glm::dvec3(s));
    auto order = [](int n, int d) { return d > 0 ? std::pair{n - 1, -1} : std::pair{0, 1}; };  // visit the far end first
    const auto [x0, dx] = order(size.x, s.x);
    const auto [y0, dy] = order(size.y, s.y);
    const auto [z0, dz] = order(size.z, s.z);
    for (int iz = 0, z = z0; iz < size.z; ++iz, z += dz)
        for (int iy = 0, y = y0; iy < size.y; ++iy, y += dy)
            for (int ix = 0, x = x0; ix < size.x; ++ix, x += dx) {
                const glm::ivec3 next(x + s.x, y + s.y, z + s.z);
                const std::size_t v = m.index(x, y, z);
                const bool inside = glm::all(glm::greaterThanEqual(next, glm::ivec3(0))) && glm::all(glm::lessThan(next, size));
                if (!inside) {
                    tau[v] = static_cast<float>(0.5 * sigma[v] * step);
                    continue;
                }
                const std::size_t n = m.index(next.x, next.y, next.z);
                tau[v] = tau[n] + static_cast<float>(0.5 * (sigma[v] + sigma[n]) * step);
            }
    return tau;
}

// Whether the ray from a point at `o` (its coordinates along a box's axes, from its centre) with
// direction `v` (along the same axes) meets the box of half-extents `half` within `reach`.
inline bool slabsMeet(const glm::dvec3& o, const glm::dvec3& v, const glm::dvec3& half, double reach) {
    double lo = 0.0, hi = reach;
    for (int a = 0; a < 3; ++a) {
        if (std::abs(v[a]) < 1e-12) {
            if (std::abs(o[a]) > half[a]) return false;
            continue;
        }
        double t0 = (-half[a] - o[a]) / v[a], t1 = (half[a] - o[a]) / v[a];
        if (t0 > t1) std::swap(t0, t1);
        lo = std::max(lo, t0);
        hi = std::min(hi, t1);
        if (lo > hi) return false;
    }
    return true;
}

// A vector's coordinates along a box's axes.
glm::dvec3 alongAxes(const glm::dvec3& d, const OccluderBox& box) {
    return {glm::dot(d, box.axis[0]), glm::dot(d, box.axis[1]), glm::dot(d, box.axis[2])};
}

// Whether the ray from p along d (unit) meets a mesh box before `reach`.
bool meetsMesh(const glm::dvec3& p, const glm::dvec3& d, const std::vector<OccluderBox>& meshes,
               double reach = std::numeric_limits<double>::infinity()) {
    for (const OccluderBox& box : meshes)
        if (slabsMeet(alongAxes(p - box.centre, box), alongAxes(d, box), box.half, reach)) return true;
    return false;
}

// The voxels' walls (diffusion.h MeshWalls): per mesh box, the voxels around it are tested, each
// centre's segment to its neighbour along +x, +y and +z against the box, and the centre itself.
MeshWalls meshWalls(const MediumGrid& m, const std::vector<OccluderBox>& meshes) {
    if (meshes.empty() || m.count() == 0) return {};
    MeshWalls walls(m.count(), 0);
    for (const OccluderBox& box : meshes) {
        const glm::dvec3 reach = axisAlignedHalf(box);
        // A segment from a centre within a voxel below the box's lower corner can reach into it.
        const glm::ivec3 lo = glm::clamp(glm::ivec3(glm::floor((box.centre - reach - m.min) / m.voxel)) - 1, glm::ivec3(0), m.size - 1);
        const glm::ivec3 hi = glm::clamp(glm::ivec3(glm::floor((box.centre + reach - m.min) / m.voxel)), glm::ivec3(0), m.size - 1);
        glm::dvec3 axes[3];
        for (int a = 0; a < 3; ++a) {
            glm::dvec3 d(0.0);
            d[a] = 1.0;
            axes[a] = alongAxes(d, box);
        }
        for (int z = lo.z; z <= hi.z; ++z)
            for (int y = lo.y; y <= hi.y; ++y)
                for (int x = lo.x; x <= hi.x; ++x) {
                    const glm::dvec3 p = m.min + (glm::dvec3(x, y, z) + 0.5) * m.voxel;
                    const glm::dvec3 o = alongAxes(p - box.centre, box);
                    std::uint8_t& bits = walls[m.index(x, y, z)];
                    for (int a = 0; a < 3; ++a)
                        if (slabsMeet(o, axes[a], box.half, m.voxel)) bits |= static_cast<std::uint8_t>(1 << a);
                    if (glm::all(glm::lessThanEqual(glm::abs(o), box.half))) bits |= kInsideMesh;
                }
    }
    return walls;
}

// The trilinear blend at u (in voxel-centre units) of fetch(voxel index) over a grid of `size`,
// each corner outside it taken as `outside` (or, with clampToEdge, as the nearest voxel).
template <typename T, typename Fetch>
T trilinear(const glm::ivec3& size, const glm::dvec3& u, Fetch fetch, bool clampToEdge) {
    const glm::ivec3 i0 = glm::ivec3(glm::floor(u));
    const glm::vec3 f = glm::vec3(u - glm::floor(u));
    T sum{0.0f};
    for (int c = 0; c < 8; ++c) {
        glm::ivec3 q = i0 + glm::ivec3(c & 1, (c >> 1) & 1, (c >> 2) & 1);
        if (clampToEdge) q = glm::clamp(q, glm::ivec3(0), size - 1);
        else if (glm::any(glm::lessThan(q, glm::ivec3(0))) || glm::any(glm::greaterThanEqual(q, size))) continue;
        const float w = (c & 1 ? f.x : 1.0f - f.x) * (c & 2 ? f.y : 1.0f - f.y) * (c & 4 ? f.z : 1.0f - f.z);
        sum += w * fetch((static_cast<std::size_t>(q.z) * static_cast<std::size_t>(size.y) + static_cast<std::size_t>(q.y)) *
                             static_cast<std::size_t>(size.x) + static_cast<std::size_t>(q.x));
    }
    return sum;
}

// σ_t at a world point: trilinear between voxel centres, zero outside the grid.
float sigmaAt(const MediumGrid& m, const glm::dvec3& world) {
    return trilinear<float>(m.size, (world - m.min) / m.voxel - 0.5, [&](std::size_t v) { return m.sigma[v]; }, false);
}

// Optical depth from p along unit d for `reach` or until the grid ends, by the midpoint rule at
// half-voxel steps.
double depthAlong(const MediumGrid& m, const glm::dvec3& p, const glm::dvec3& d, double reach) {
    const glm::dvec3 lo = m.min, hi = m.min + glm::dvec3(m.size) * m.voxel;
    double exit = reach;
    for (int a = 0; a < 3; ++a)
        if (std::abs(d[a]) > 1e-12) exit = std::min(exit, ((d[a] > 0.0 ? hi[a] : lo[a]) - p[a]) / d[a]);
    const double step = 0.5 * m.voxel;
    double tau = 0.0;
    for (double t = 0.5 * step; t < exit; t += step) tau += sigmaAt(m, p + d * t) * std::min(step, exit - t + 0.5 * step);
    return tau;
}

// Per voxel, the mean transmittance to the outside over the 14 lattice directions, mesh boxes dark,
// and its first moment, the mean of T·d over the same directions.
struct EnvironmentTransmittance {
    std::vector<float> mean;
    std::vector<glm::vec3> moment;
};
EnvironmentTransmittance environmentTransmittance(const MediumGrid& m, const std::vector<OccluderBox>& meshes) {
    std::vector<glm::ivec3> steps;  // in the order each voxel sums their shares
    for (int z = -1; z <= 1; ++z)
        for (int y = -1; y <= 1; ++y)
            for (int x = -1; x <= 1; ++x)
                if (std::abs(x) + std::abs(y) + std::abs(z) == 1 || (x != 0 && y != 0 && z != 0)) steps.emplace_back(x, y, z);
    std::vector<glm::dvec3> directions;
    for (const glm::ivec3& step : steps) directions.push_back(glm::normalize(glm::dvec3(step)));
    std::vector<std::vector<float>> tau(steps.size());
    tbb::parallel_for(std::size_t(0), steps.size(), [&](std::size_t s) { tau[s] = sweep(m, steps[s]); });
    // Each direction along each box's axes, and per voxel its position along them, once: the ray
    // tests differ only in the slabs' arithmetic.
    std::vector<glm::dvec3> directionAlong(steps.size() * meshes.size());
    for (std::size_t s = 0; s < steps.size(); ++s)
        for (std::size_t b = 0; b < meshes.size(); ++b) directionAlong[s * meshes.size() + b] = alongAxes(directions[s], meshes[b]);
    EnvironmentTransmittance out{std::vector<float>(m.count(), 0.0f), std::vector<glm::vec3>(m.count(), glm::vec3(0.0f))};
    forEachSlab(m.size, [&](int k) {
        std::vector<glm::dvec3> pointAlong(meshes.size());
        for (int j = 0; j < m.size.y; ++j)
            for (int i = 0; i < m.size.x; ++i) {
                const std::size_t v = m.index(i, j, k);
                const glm::dvec3 p = m.min + (glm::dvec3(i, j, k) + 0.5) * m.voxel;
                for (std::size_t b = 0; b < meshes.size(); ++b) pointAlong[b] = alongAxes(p - meshes[b].centre, meshes[b]);
                const auto blocked = [&](std::size_t s) {
                    for (std::size_t b = 0; b < meshes.size(); ++b)
                        if (slabsMeet(pointAlong[b], directionAlong[s * meshes.size() + b], meshes[b].half, std::numeric_limits<double>::infinity()))
                            return true;
                    return false;
                };
                for (std::size_t s = 0; s < steps.size(); ++s) {
                    const glm::dvec3& d = directions[s];
                    if (blocked(s)) continue;
                    const float t = std::exp(-tau[s][v]) / 14.0f;
                    out.mean[v] += t;
                    out.moment[v] += t * glm::vec3(d);
                }
            }
    });
    return out;
}

// Q per voxel: σ_s times the light that arrives unscattered, from the lights and the environment
// (4π L_amb times the mean transmittance), and the medium's own emission (fire), which the passes
// draw unscattered and this scatters. δ-Eddington scaling (Joseph, Wiscombe and Weinman): the
// fraction f = g² of scattering in the forward peak counts as unscattered, so light reaches deeper
// (through σ_t − f·σ_s) and the diffuse source keeps (1 − f) of it.
std::vector<glm::vec3> firstScattering(const MediumGrid& original, const EnvironmentLighting& lighting, const std::vector<float>& environment) {
    std::vector<glm::vec3> source(original.count(), glm::vec3(0.0f));
    MediumGrid scaled = original;
    std::vector<float> keep(original.count(), 1.0f);
    for (std::size_t v = 0; v < original.count(); ++v) {
        if (!(original.sigma[v] > 0.0f)) continue;
        const float g = original.sigmaG[v] / original.sigma[v];
        const float f = g * g;
        const float sigmaS = glm::dot(original.scattering[v], kLuminanceWeights);
        scaled.sigma[v] = original.sigma[v] - f * sigmaS;
        keep[v] = 1.0f - f;
    }
    const MediumGrid& m = scaled;
    static const std::vector<OccluderBox> kNoMeshes;
    const std::vector<OccluderBox>& meshes = lighting.meshes != nullptr ? *lighting.meshes : kNoMeshes;
    forEachSlab(m.size, [&](int z) {
        for (int y = 0; y < m.size.y; ++y)
            for (int x = 0; x < m.size.x; ++x) {
                const std::size_t v = m.index(x, y, z);
                if (!(m.sigma[v] > 0.0f)) continue;
                const glm::dvec3 p = m.min + (glm::dvec3(x, y, z) + 0.5) * m.voxel;
                glm::vec3 arriving = lighting.ambient * (4.0f * static_cast<float>(kPi) * environment[v]);
                if (lighting.lights != nullptr)
                    for (const Light& light : *lighting.lights) {
                        const Arrival a = arrival(light, p);
                        const VoxelLight e = voxelIrradiance(light, p, m.voxel, m.sigma[v], a);
                        if (!(e.irradiance.x + e.irradiance.y + e.irradiance.z > 0.0f)) continue;
                        if (!meshes.empty() && meetsMesh(p, a.toLight, meshes, a.distance)) continue;
                        arriving += e.irradiance * static_cast<float>(std::exp(-depthAlong(m, p, a.toLight, a.distance)) * e.scale);
                    }
                source[v] = keep[v] * m.scattering[v] * arriving + 4.0f * static_cast<float>(kPi) * m.emission[v];  // emission: all directions
            }
    });
    return source;
}

// φ with each voxel that holds no medium given the mean of its neighbours that do: the passes
// read the grid trilinearly, and a particle at the medium's surface should see the surface's
// scattered light rather than a ramp to the empty voxel's zero.
std::vector<glm::vec3> dilated(const MediumGrid& m, const std::vector<glm::vec3>& phi) {
    std::vector<glm::vec3> out = phi;
    // Per voxel, whether it or a neighbour along x holds light: most empty voxels have none of the
    // 27 around them, and the 9 rows' flags tell it without the mean.
    std::vector<char> nearX(phi.size(), 0);
    forEachSlab(m.size, [&](int z) {  // a slab writes its own rows' flags only
        for (int y = 0; y < m.size.y; ++y)
            for (int x = 0; x < m.size.x; ++x) {
                if (phi[m.index(x, y, z)] == glm::vec3(0.0f)) continue;
                for (int dx = std::max(x - 1, 0); dx <= std::min(x + 1, m.size.x - 1); ++dx) nearX[m.index(dx, y, z)] = 1;
            }
    });
    forEachSlab(m.size, [&](int z) {
        for (int y = 0; y < m.size.y; ++y)
            for (int x = 0; x < m.size.x; ++x) {
                const std::size_t v = m.index(x, y, z);
                if (phi[v] != glm::vec3(0.0f)) continue;
                // The 27 around it inside the grid.
                const glm::ivec3 lo = glm::max(glm::ivec3(x, y, z) - 1, glm::ivec3(0)), hi = glm::min(glm::ivec3(x, y, z) + 1, m.size - 1);
                bool any = false;
                for (int dz = lo.z; dz <= hi.z && !any; ++dz)
                    for (int dy = lo.y; dy <= hi.y && !any; ++dy) any = nearX[m.index(x, dy, dz)] != 0;
                if (!any) continue;
                glm::vec3 sum(0.0f);
                int count = 0;
                for (int qz = lo.z; qz <= hi.z; ++qz)
                    for (int qy = lo.y; qy <= hi.y; ++qy)
                        for (int qx = lo.x; qx <= hi.x; ++qx) {  // x fastest: the sum's order is fixed
                            const glm::vec3& n = phi[m.index(qx, qy, qz)];
                            if (n == glm::vec3(0.0f)) continue;
                            sum += n;
                            ++count;
                        }
                if (count > 0) out[v] = sum / static_cast<float>(count);
            }
    });
    return out;
}

// Per voxel the P1 anisotropy a of environment_grid.h (0 where the source is 0), dilated into empty
// voxels as φ is.
std::vector<glm::vec4> directionalTexels(const MediumGrid& m, const glm::vec3& ambient, const EnvironmentTransmittance& environment,
                                         const std::vector<glm::vec3>& radiance, const std::vector<glm::vec3>& flux) {
    const float ambientLuminance = glm::dot(ambient, kLuminanceWeights);
    const float inv4Pi = 1.0f / (4.0f * static_cast<float>(kPi));
    std::vector<glm::vec3> a(m.count(), glm::vec3(0.0f));
    std::vector<glm::vec3> weight(m.count(), glm::vec3(0.0f));
    const auto slab = static_cast<std::size_t>(slabVoxels(m.size));
    forEachSlab(m.size, [&](int z) {
        for (std::size_t v = static_cast<std::size_t>(z) * slab; v < (static_cast<std::size_t>(z) + 1) * slab; ++v) {
            const float base = ambientLuminance * environment.mean[v] + glm::dot(radiance[v], kLuminanceWeights) * inv4Pi;
            if (!(base > 0.0f) || !(m.sigma[v] > 0.0f)) continue;
            const glm::vec3 p1 = (3.0f * inv4Pi * flux[v] - 3.0f * ambientLuminance * environment.moment[v]) / base;
            // A radiance x(1 + a·ω) is negative somewhere where |a| > 1, as P1 gives at a lit rim where the
            // light is far from linear in direction: |a| is kept at most 1.
            a[v] = p1 / std::max(1.0f, glm::length(p1));
            weight[v] = glm::vec3(1.0f);
        }
    });
    const std::vector<glm::vec3> spread = dilated(m, a), count = dilated(m, weight);
    std::vector<glm::vec4> out(m.count(), glm::vec4(0.0f));
    for (std::size_t v = 0; v < m.count(); ++v)
        if (count[v].x > 0.0f) out[v] = glm::vec4(spread[v] / count[v].x, 0.0f);
    return out;
}

// `coarse`'s fluence at `fine`'s voxel centres, trilinear: where a solve on the finer grid starts.
std::vector<glm::vec3> resampled(const EnvironmentGrid& coarse, const MediumGrid& fine) {
    std::vector<glm::vec3> out(fine.count(), glm::vec3(0.0f));
    if (coarse.fluence.empty()) return out;
    for (int z = 0; z < fine.size.z; ++z)
        for (int y = 0; y < fine.size.y; ++y)
            for (int x = 0; x < fine.size.x; ++x) {
                const glm::dvec3 u = (fine.min + (glm::dvec3(x, y, z) + 0.5) * fine.voxel - coarse.min) / coarse.voxel.x - 0.5;
                out[fine.index(x, y, z)] = trilinear<glm::vec3>(coarse.size, u, [&](std::size_t v) { return coarse.fluence[v]; }, true);
            }
    return out;
}

// Every number of the medium (particles and volumes, before voxelizing), the mesh boxes, and the
// grid's size and sweep budgets. With lightingKey, what a frame that keeps the last answer must have
// the same; comparing these, not the voxelized medium, spares that frame the voxelizing.
std::vector<double> inputKey(const ParticleSet& particles, const std::vector<Volume>& volumes, const std::vector<OccluderBox>* meshes,
                             int voxelsAlongLongest, const DiffusionSolve& solve) {
    std::vector<double> key{static_cast<double>(voxelsAlongLongest), static_cast<double>(solve.maxSweeps),
                            static_cast<double>(solve.warmSweeps)};
    key.reserve(key.size() + 12 * particles.size());
    for (std::size_t i = 0; i < particles.size(); ++i) {
        const glm::dvec3& p = particles.position[i];
        const glm::vec3 &a = particles.albedo[i], &e = particles.emission[i];
        key.insert(key.end(), {p.x, p.y, p.z, particles.radius[i], particles.sigma[i], a.x, a.y, a.z, e.x, e.y, e.z, particles.g[i]});
    }
    for (const Volume& v : volumes) {
        key.insert(key.end(), {static_cast<double>(v.shape), v.size.x, v.size.y, v.size.z, v.drift.x, v.drift.y, v.drift.z,
                               v.medium.extinction, v.medium.albedo.x, v.medium.albedo.y, v.medium.albedo.z, v.medium.g,
                               v.medium.emission.x, v.medium.emission.y, v.medium.emission.z});
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) key.push_back(v.world[c][r]);
        if (const std::optional<NoiseField>& n = v.noise)
            key.insert(key.end(), {static_cast<double>(n->kind), static_cast<double>(n->octaves), n->frequency, static_cast<double>(n->seed),
                                   n->gain, n->coverage, n->falloff});
        else
            key.push_back(-1.0);
    }
    if (meshes != nullptr)
        for (const OccluderBox& b : *meshes) {
            key.insert(key.end(), {b.centre.x, b.centre.y, b.centre.z, b.half.x, b.half.y, b.half.z});
            for (const glm::dvec3& a : b.axis) key.insert(key.end(), {a.x, a.y, a.z});
        }
    return key;
}

// The lights and ambient, every number of them.
std::vector<double> lightingKey(const EnvironmentLighting& lighting) {
    std::vector<double> key{lighting.ambient.x, lighting.ambient.y, lighting.ambient.z};
    if (lighting.lights != nullptr)
        for (const Light& l : *lighting.lights)
            key.insert(key.end(), {static_cast<double>(l.kind), l.position.x, l.position.y, l.position.z, l.direction.x, l.direction.y,
                                   l.direction.z, l.radiance.x, l.radiance.y, l.radiance.z, l.range, l.innerConeAngle, l.outerConeAngle});
    return key;
}

// Whether a warm start (DiffusionSolve::warmSweeps) may follow the lights from the grid's to
// `now`'s: the same lights, each turned by at most kWarmTurn, moved by at most a voxel, and its
// light and the ambient changed by at most kWarmChange, as a sun crossing the sky or a carried
// lamp does from frame to frame. A light switched on or off, or one that jumped, would take many
// frames of a few sweeps to show its scattering, so it is solved cold.
constexpr double kWarmTurn = 0.035;   // radians, 2 degrees
constexpr double kWarmChange = 0.1;   // relative
bool lightsClose(const EnvironmentGrid& last, const EnvironmentLighting& now) {
    static const std::vector<Light> kNone;
    const std::vector<Light>& lights = now.lights != nullptr ? *now.lights : kNone;
    const auto close = [](double a, double b) { return std::abs(a - b) <= kWarmChange * std::max(std::abs(a), std::abs(b)); };
    const auto closeRgb = [&](const glm::vec3& a, const glm::vec3& b) { return close(a.x, b.x) && close(a.y, b.y) && close(a.z, b.z); };
    if (last.lights.size() != lights.size() || !closeRgb(last.ambient, now.ambient)) return false;
    for (std::size_t i = 0; i < lights.size(); ++i) {
        const Light &a = last.lights[i], &b = lights[i];
        if (a.kind != b.kind || !closeRgb(a.radiance, b.radiance) || !close(a.range, b.range) ||
            !close(a.innerConeAngle, b.innerConeAngle) || !close(a.outerConeAngle, b.outerConeAngle))
            return false;
        if (a.kind != gpu::LightKind::Directional && glm::length(a.position - b.position) > last.voxel.x) return false;
        if (a.kind != gpu::LightKind::Point && glm::dot(a.direction, b.direction) < std::cos(kWarmTurn)) return false;  // unit directions
    }
    return true;
}

// scattering_warm_sweeps relax less: from a start the medium has moved away from, 1.9 overshoots
// before it settles (a dense particle moved by 0.4 voxel came out 2.4× its cold solve after 8
// sweeps; at 1.5, 3% under it).
constexpr float kWarmOverRelaxation = 1.5f;

// What every level of the solve makes: the grid's frame, its environment transmittance, the first
// scattering and the fluence solved from it (started from `solve.coarser`'s where given).
struct Level {
    EnvironmentTransmittance environment;
    std::vector<glm::vec3> source;
    MeshWalls walls;
};
Level solveLevel(const MediumGrid& medium, const EnvironmentLighting& lighting, const DiffusionSolve& solve, EnvironmentGrid& grid) {
    static const std::vector<OccluderBox> kNoMeshes;
    Level level;
    if (medium.count() > 0) {
        const std::vector<OccluderBox>& meshes = lighting.meshes != nullptr ? *lighting.meshes : kNoMeshes;
        level.environment = environmentTransmittance(medium, meshes);
        level.source = firstScattering(medium, lighting, level.environment.mean);
        level.walls = meshWalls(medium, meshes);
    }
    grid.sweeps = 0;
    grid.rescatter = 0.0f;
    grid.size = medium.size;
    grid.min = medium.min;
    grid.voxel = glm::dvec3(medium.voxel);
    grid.texels.clear();
    grid.directional.clear();
    grid.fluence = solve.coarser != nullptr ? resampled(*solve.coarser, medium) : std::vector<glm::vec3>{};
    DiffusionSolve walled = solve;
    walled.walls = &level.walls;
    if (medium.count() > 0) grid.sweeps = solveDiffusion(medium, level.source, grid.fluence, walled);
    return level;
}

// The fluence alone on a grid of `voxels` along the longest side, its solve started from a grid of
// half as many (down to 4): the diffusion's long wavelengths converge on a coarser grid first. A
// finer level reads nothing else of it, so nothing else is built.
void solveCoarser(const ParticleSet& particles, const std::vector<Volume>& volumes, const EnvironmentLighting& lighting, int voxels,
                  DiffusionSolve solve, EnvironmentGrid& level) {
    EnvironmentGrid coarser;
    if (voxels >= 8) {
        solveCoarser(particles, volumes, lighting, voxels / 2, solve, coarser);
        solve.coarser = &coarser;
    }
    solveLevel(voxelizeMedium(particles, volumes, voxels), lighting, solve, level);
}

}  // namespace

void solveEnvironmentGrid(const ParticleSet& particles, const std::vector<Volume>& volumes, const EnvironmentLighting& lighting,
                          int voxelsAlongLongest, DiffusionSolve solve, EnvironmentGrid& grid) {
    std::vector<double> key = inputKey(particles, volumes, lighting.meshes, voxelsAlongLongest, solve);
    const bool same = !grid.texels.empty() && grid.inputs == key &&
                      lightingKey({.lights = &grid.lights, .ambient = grid.ambient}) == lightingKey(lighting);
    if (same && !grid.warm) {
        grid.sweeps = 0;
        return;
    }
    // A warm answer whose medium stopped is solved cold once, so a still frame's picture is its own.
    EnvironmentGrid start;
    const bool warm = !same && solve.warmSweeps > 0 && !grid.fluence.empty() && lightsClose(grid, lighting);
    if (warm) {
        // scattering_warm_sweeps: the last frame's fluence, where the medium and lights were close
        // to this frame's, is nearer this answer than a coarser grid's.
        start = std::move(grid);
        solve.maxSweeps = std::min(solve.maxSweeps, solve.warmSweeps);
        solve.overRelaxation = kWarmOverRelaxation;
        solve.coarser = &start;
    } else if (voxelsAlongLongest >= 8) {
        // Otherwise never from the last frame's answer: a frame's picture depends on that frame alone.
        solveCoarser(particles, volumes, lighting, voxelsAlongLongest / 2, solve, start);
        solve.coarser = &start;
    }
    grid = {};
    buildEnvironmentGrid(voxelizeMedium(particles, volumes, voxelsAlongLongest), lighting, solve, grid);
    grid.inputs = std::move(key);
    grid.lights = lighting.lights != nullptr ? *lighting.lights : std::vector<Light>{};
    grid.ambient = lighting.ambient;
    grid.warm = warm;
}

MediumGrid voxelizeMedium(const ParticleSet& particles, const std::vector<Volume>& volumes, int voxelsAlongLongest) {
    MediumGrid m;
    Aabb bounds = volumeBounds(volumes);
    for (std::size_t i = 0; i < particles.size(); ++i) {
        bounds.extend(particles.position[i] - glm::dvec3(particles.radius[i]));
        bounds.extend(particles.position[i] + glm::dvec3(particles.radius[i]));
    }
    if (bounds.empty()) return m;
    const glm::dvec3 extent = bounds.max - bounds.min;
    m.voxel = std::max({extent.x, extent.y, extent.z, 1e-6}) / std::max(voxelsAlongLongest, 1);
    m.min = bounds.min - m.voxel;  // a voxel of padding: outside the medium everything is lit
    m.size = glm::ivec3(glm::ceil(extent / m.voxel)) + 2;
    const std::size_t n = static_cast<std::size_t>(m.size.x) * static_cast<std::size_t>(m.size.y) * static_cast<std::size_t>(m.size.z);
    m.sigma.assign(n, 0.0f);
    m.scattering.assign(n, glm::vec3(0.0f));
    m.sigmaG.assign(n, 0.0f);
    m.emission.assign(n, glm::vec3(0.0f));
    for (std::size_t i = 0; i < particles.size(); ++i) splatParticle(particles, i, m);
    for (const Volume& vol : volumes)
        for (int z = 0; z < m.size.z; ++z)
            for (int y = 0; y < m.size.y; ++y)
                for (int x = 0; x < m.size.x; ++x) {
                    const float sigma = static_cast<float>(volumeExtinction(vol, m.min + (glm::dvec3(x, y, z) + 0.5) * m.voxel));
                    if (!(sigma > 0.0f)) continue;
                    const std::size_t v = m.index(x, y, z);
                    m.sigma[v] += sigma;
                    m.scattering[v] += sigma * vol.medium.albedo;
                    m.sigmaG[v] += sigma * vol.medium.g;
                    m.emission[v] += sigma * vol.medium.emission;
                }
    return m;
}

void buildEnvironmentGrid(const MediumGrid& medium, const EnvironmentLighting& lighting, const DiffusionSolve& solve, EnvironmentGrid& grid) {
    const Level level = solveLevel(medium, lighting, solve, grid);
    if (medium.count() == 0) return;
    const EnvironmentTransmittance& environment = level.environment;
    const float inv4Pi = 1.0f / (4.0f * static_cast<float>(kPi));
    const std::vector<glm::vec3> radiance = dilated(medium, grid.fluence);
    double again = 0.0, first = 0.0;  // the first scattering's light, weighted by the chance it scatters again
    for (std::size_t v = 0; v < medium.count(); ++v)
        if (medium.sigma[v] > 0.0f) {
            const double q = glm::dot(level.source[v], kLuminanceWeights), albedo = glm::dot(medium.scattering[v], kLuminanceWeights) / medium.sigma[v];
            first += q;
            again += q * albedo * (1.0 - environment.mean[v]);
        }
    grid.rescatter = first > 0.0 ? static_cast<float>(again / first) : 0.0f;
    grid.texels.resize(medium.count());
    for (std::size_t v = 0; v < medium.count(); ++v) grid.texels[v] = glm::vec4(environment.mean[v], radiance[v] * inv4Pi);
    grid.directional = directionalTexels(medium, lighting.ambient, environment, radiance, diffusionFlux(medium, grid.fluence, &level.walls));
}

}  // namespace nimbus::media
