#include "nimbus/media/particle_bvh.h"

#include <algorithm>

namespace nimbus::media {
namespace {

constexpr std::uint32_t kLeafSize = 4;

}  // namespace

void ParticleBvh::build(const ParticleSet& particles) {
    nodes_.clear();
    spheres_.clear();
    spheres_.reserve(particles.size());
    for (std::size_t i = 0; i < particles.size(); ++i) {
        const double r = particles.radius[i];
        if (!(r > 0.0) || !(particles.sigma[i] > 0.0)) continue;
        spheres_.push_back({particles.position[i], r * r, static_cast<std::uint32_t>(i)});
    }
    if (spheres_.empty()) return;
    nodes_.reserve(2 * spheres_.size() / kLeafSize + 2);

    // Iterative top-down build: split at the median centroid along the widest centroid axis. Median
    // splits keep the depth at log2(N) (the traversal stack is fixed-size) and, with ties broken by
    // particle index, make the tree a pure function of the input.
    struct Task {
        std::uint32_t node, first, count;
    };
    std::vector<Task> tasks;
    nodes_.push_back({});
    tasks.push_back({0, 0, static_cast<std::uint32_t>(spheres_.size())});
    while (!tasks.empty()) {
        const Task task = tasks.back();
        tasks.pop_back();
        glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
        glm::dvec3 clo = lo, chi = hi;
        for (std::uint32_t s = task.first; s < task.first + task.count; ++s) {
            const double r = std::sqrt(spheres_[s].radius2);
            lo = glm::min(lo, spheres_[s].centre - r);
            hi = glm::max(hi, spheres_[s].centre + r);
            clo = glm::min(clo, spheres_[s].centre);
            chi = glm::max(chi, spheres_[s].centre);
        }
        nodes_[task.node].min = lo;
        nodes_[task.node].max = hi;
        if (task.count <= kLeafSize) {
            nodes_[task.node].first = task.first;
            nodes_[task.node].count = task.count;
            continue;
        }
        const glm::dvec3 extent = chi - clo;
        const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
        const std::uint32_t half = task.count / 2;
        auto begin = spheres_.begin() + task.first;
        std::nth_element(begin, begin + half, begin + task.count, [axis](const Sphere& a, const Sphere& b) {
            return a.centre[axis] < b.centre[axis] || (a.centre[axis] == b.centre[axis] && a.particle < b.particle);
        });
        const auto left = static_cast<std::uint32_t>(nodes_.size());
        nodes_.push_back({});
        nodes_.push_back({});
        nodes_[task.node].first = left;
        nodes_[task.node].count = 0;
        nodes_[task.node].axis = static_cast<std::uint8_t>(axis);
        tasks.push_back({left + 1, task.first + half, task.count - half});
        tasks.push_back({left, task.first, half});
    }
}

std::vector<std::uint32_t> ParticleBvh::particlesOnSegment(const glm::dvec3& origin, const glm::dvec3& dir, double t0,
                                                           double t1) const {
    std::vector<std::uint32_t> out;
    forEachOnSegment(origin, dir, t0, t1, [&](std::uint32_t i) {
        out.push_back(i);
        return true;
    });
    return out;
}

std::vector<std::uint32_t> ParticleBvh::particlesContaining(const glm::dvec3& x) const {
    std::vector<std::uint32_t> out;
    forEachContaining(x, [&](std::uint32_t i) {
        out.push_back(i);
        return true;
    });
    return out;
}

}  // namespace nimbus::media
