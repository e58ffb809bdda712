#include "common/lamp_neighbourhood.h"

#include <algorithm>
#include <cstring>
#include <limits>

namespace nimbus::media {

bool anyLamp(const std::vector<Light>& lights) {
    return std::any_of(lights.begin(), lights.end(), [](const Light& light) {
        return light.kind != gpu::LightKind::Directional;
    });
}

void LampNeighbourhoods::find(const ParticleSet& particles, const std::vector<Light>& lights,
                              const std::vector<std::uint32_t>& rankOf, LampsListed which, double minimumReach) {
    lamps.assign(lights.size(), LampNeighbourhood{});
    neighbours.clear();
    if (!anyLamp(lights)) return;
    for (std::size_t l = 0; l < lights.size(); ++l) {
        if (lights[l].kind == gpu::LightKind::Directional) continue;
        const glm::dvec3 lamp = lights[l].position;
        double largestContaining = 0.0, nearestGap = std::numeric_limits<double>::infinity(), nearestRadius = 0.0;
        for (std::size_t i = 0; i < particles.size(); ++i) {
            const double gap = glm::length(particles.position[i] - lamp) - particles.radius[i];
            if (gap < 0.0) largestContaining = std::max(largestContaining, static_cast<double>(particles.radius[i]));
            if (gap < nearestGap) {
                nearestGap = gap;
                nearestRadius = particles.radius[i];
            }
        }
        double reach = largestContaining > 0.0 || which == LampsListed::InsideMedium ? largestContaining : nearestRadius;
        if (which == LampsListed::All) reach = std::max(reach, minimumReach);
        if (reach <= 0.0) continue;
        candidates_.clear();
        for (std::size_t i = 0; i < particles.size(); ++i) {
            const double distance = glm::length(particles.position[i] - lamp);
            if (distance >= particles.radius[i] + reach) continue;
            // InsideMedium: closest relative to their radius first (the most mass at the lamp). All:
            // by the gap between sphere and lamp, so that the list is complete up to the first left out.
            const double key = which == LampsListed::InsideMedium ? distance / particles.radius[i] : distance - particles.radius[i];
            candidates_.emplace_back(key, static_cast<std::uint32_t>(i));
        }
        std::sort(candidates_.begin(), candidates_.end());  // ties by index, so deterministic
        if (candidates_.size() > kMaxLampNeighbours) {
            if (which == LampsListed::All) reach = candidates_[kMaxLampNeighbours].first;  // may be ≤ 0: then nothing is trusted
            candidates_.resize(kMaxLampNeighbours);
        }
        LampNeighbourhood& entry = lamps[l];
        entry.first = static_cast<std::uint32_t>(neighbours.size());
        entry.count = static_cast<std::uint32_t>(candidates_.size());
        entry.reach = static_cast<float>(std::max(reach, 0.0));
        for (const auto& [key, index] : candidates_) neighbours.emplace_back(index, index < rankOf.size() ? rankOf[index] : 0u);
    }
}

void LampNeighbourhoodBuffer::upload(const LampNeighbourhoods& n) {
    // Layout (lamp_neighbourhood.glsl): uvec4 per lamp, then uvec2 per neighbour.
    const std::size_t headerWords = n.lamps.size() * 4, words = headerWords + n.neighbours.size() * 2;
    staging_.assign(std::max<std::size_t>(words, 4), 0u);
    for (std::size_t l = 0; l < n.lamps.size(); ++l) {
        staging_[4 * l] = n.lamps[l].first;
        staging_[4 * l + 1] = n.lamps[l].count;
        std::memcpy(&staging_[4 * l + 2], &n.lamps[l].reach, sizeof(float));
    }
    for (std::size_t i = 0; i < n.neighbours.size(); ++i) {
        staging_[headerWords + 2 * i] = n.neighbours[i].x;
        staging_[headerWords + 2 * i + 1] = n.neighbours[i].y;
    }
    const std::size_t bytes = staging_.size() * sizeof(std::uint32_t);
    if (!buffer_ || capacity_ < bytes) {
        capacity_ = std::max(bytes, capacity_ * 3 / 2);
        buffer_ = gpu::createBuffer(capacity_, nullptr, GL_DYNAMIC_STORAGE_BIT);
    }
    glNamedBufferSubData(buffer_.id(), 0, static_cast<GLsizeiptr>(bytes), staging_.data());
}

}  // namespace nimbus::media
