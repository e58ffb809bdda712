#include "particle_buffer.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace nimbus::media {
namespace {

void ensureCapacity(gpu::Buffer& buffer, std::size_t& capacity, std::size_t bytes) {
    if (buffer && capacity >= bytes) return;
    capacity = std::max<std::size_t>(bytes, capacity * 3 / 2);
    buffer = gpu::createBuffer(capacity, nullptr, GL_DYNAMIC_STORAGE_BIT);
}

}  // namespace

void ParticleGpuBuffer::upload(const ParticleSet& p, const glm::dvec3& origin) {
    count_ = p.size();
    staging_.resize(count_);
    for (std::size_t i = 0; i < count_; ++i) {
        staging_[i].positionRadius = glm::vec4(glm::vec3(p.position[i] - origin), p.radius[i]);
        staging_[i].albedoSigma = glm::vec4(p.albedo[i], p.sigma[i]);
        staging_[i].emissionG = glm::vec4(p.emission[i], p.g[i]);
        staging_[i].extra = glm::vec4(p.phase[i] == PhaseFunction::Rayleigh ? 1.0f : 0.0f, 0.0f, 0.0f, 0.0f);
    }
    ensureCapacity(particles_, particleCapacity_, std::max<std::size_t>(count_, 1) * sizeof(GpuParticle));
    if (count_ > 0) glNamedBufferSubData(particles_.id(), 0, static_cast<GLsizeiptr>(count_ * sizeof(GpuParticle)), staging_.data());
}

double visibleDepthOffset(double sigma, double radius) {
    const double deviation = radius / 3.0;
    const double column = sigma * deviation * 2.5066282746310002;  // √(2π) s σ: through the centre
    if (!(column > 1e-3)) return 0.0;
    const double fraction = (1.0 - (1.0 + column) * std::exp(-column)) / (column * -std::expm1(-column));
    // The kernel (cut at ±3 deviations) holds `fraction` of its depth in front of z deviations
    // where erf(z/√2) = erf(3/√2)·(2·fraction − 1): Winitzki's closed form of erf⁻¹, then two
    // Newton steps on erf.
    const double x = 0.99730020393673979 * (2.0 * fraction - 1.0);
    const double a = 0.147, ln = std::log(1.0 - x * x), first = 2.0 / (3.14159265358979 * a) + 0.5 * ln;
    double w = std::copysign(std::sqrt(std::sqrt(first * first - ln / a) - first), x);
    for (int step = 0; step < 2; ++step) w -= (std::erf(w) - x) / (1.1283791670955126 * std::exp(-w * w));
    return std::clamp(-1.4142135623730951 * w * deviation, 0.0, radius);
}

void ParticleGpuBuffer::sortBackToFront(const ParticleSet& p, const render::View& view) {
    order_cpu_.resize(p.size());
    keys_.resize(p.size());
    std::iota(order_cpu_.begin(), order_cpu_.end(), 0u);
    for (std::size_t i = 0; i < p.size(); ++i) {
        const glm::dvec3 d = p.position[i] - view.origin;
        // Perspective: distance from the eye; orthographic: depth along the view axis.
        const double centre = view.orthographic ? glm::dot(d, view.forward) : glm::length(d);
        keys_[i] = static_cast<float>(centre - visibleDepthOffset(p.sigma[i], p.radius[i]));
    }
    // Stable, so equal keys keep a deterministic order.
    std::stable_sort(order_cpu_.begin(), order_cpu_.end(), [&](std::uint32_t a, std::uint32_t b) { return keys_[a] > keys_[b]; });
    ensureCapacity(order_, orderCapacity_, std::max<std::size_t>(order_cpu_.size(), 1) * sizeof(std::uint32_t));
    if (!order_cpu_.empty())
        glNamedBufferSubData(order_.id(), 0, static_cast<GLsizeiptr>(order_cpu_.size() * sizeof(std::uint32_t)), order_cpu_.data());
}

void ParticleGpuBuffer::uploadLampNeighbourhoods(const ParticleSet& particles, const std::vector<assets::ResolvedLight>& lights) {
    rank_.assign(particles.size(), 0u);
    for (std::size_t r = 0; r < order_cpu_.size() && r < rank_.size(); ++r) rank_[order_cpu_[r]] = static_cast<std::uint32_t>(r);
    uploadLampNeighbourhoods(particles, lights, rank_, LampsListed::InsideMedium);
}

void ParticleGpuBuffer::uploadLampNeighbourhoods(const ParticleSet& particles, const std::vector<assets::ResolvedLight>& lights,
                                                 const std::vector<std::uint32_t>& rankOf, LampsListed which, double minimumReach) {
    lamps_.find(particles, lights, rankOf, which, minimumReach);
    lampBuffer_.upload(lamps_);
}

}  // namespace nimbus::media
