#include "common/particle_buffer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
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

void sortDescending(const std::vector<float>& keys, std::vector<std::uint32_t>& order, std::vector<std::uint32_t>& scratch) {
    const std::size_t n = keys.size();
    order.resize(n);
    scratch.resize(n);
    std::iota(order.begin(), order.end(), 0u);
    // A float's bits made to order as unsigned integers, inverted so the largest key comes first.
    auto rank = [&](std::uint32_t i) {
        std::uint32_t bits = 0;
        const float key = keys[i] + 0.0f;  // −0 and +0 are one key, as for operator>
        std::memcpy(&bits, &key, sizeof bits);
        return ~(bits & 0x80000000u ? ~bits : bits | 0x80000000u);
    };
    for (int shift = 0; shift < 32; shift += 8) {
        std::array<std::uint32_t, 257> start{};
        for (std::size_t k = 0; k < n; ++k) ++start[((rank(order[k]) >> shift) & 0xFFu) + 1];
        for (std::size_t b = 1; b < start.size(); ++b) start[b] += start[b - 1];
        for (std::size_t k = 0; k < n; ++k) scratch[start[(rank(order[k]) >> shift) & 0xFFu]++] = order[k];
        order.swap(scratch);
    }
}

void ParticleGpuBuffer::sortBackToFront(const ParticleSet& p, const gpu::View& view) {
    keys_.resize(p.size());
    offsets_.resize(p.size());
    offsetInputs_.resize(p.size(), glm::vec2(-1.0f));
    for (std::size_t i = 0; i < p.size(); ++i) {
        const glm::vec2 inputs(p.sigma[i], p.radius[i]);
        if (inputs != offsetInputs_[i]) {
            offsets_[i] = visibleDepthOffset(p.sigma[i], p.radius[i]);
            offsetInputs_[i] = inputs;
        }
    }
    for (std::size_t i = 0; i < p.size(); ++i) {
        const glm::dvec3 d = p.position[i] - view.origin;
        // Perspective: distance from the eye; orthographic: depth along the view axis.
        const double centre = view.orthographic ? glm::dot(d, view.forward) : glm::length(d);
        keys_[i] = static_cast<float>(centre - offsets_[i]);
    }
    sortDescending(keys_, order_cpu_, sortScratch_);
    ensureCapacity(order_, orderCapacity_, std::max<std::size_t>(order_cpu_.size(), 1) * sizeof(std::uint32_t));
    if (!order_cpu_.empty())
        glNamedBufferSubData(order_.id(), 0, static_cast<GLsizeiptr>(order_cpu_.size() * sizeof(std::uint32_t)), order_cpu_.data());
}

void ParticleGpuBuffer::sortByViewDepth(const ParticleSet& p, const gpu::View& view) {
    keys_.resize(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) keys_[i] = static_cast<float>(glm::dot(p.position[i] - view.origin, view.forward));
    sortDescending(keys_, order_cpu_, sortScratch_);
    rankDepths_.resize(order_cpu_.size());
    for (std::size_t r = 0; r < order_cpu_.size(); ++r) rankDepths_[r] = keys_[order_cpu_[r]];
    ensureCapacity(order_, orderCapacity_, std::max<std::size_t>(order_cpu_.size(), 1) * sizeof(std::uint32_t));
    if (!order_cpu_.empty())
        glNamedBufferSubData(order_.id(), 0, static_cast<GLsizeiptr>(order_cpu_.size() * sizeof(std::uint32_t)), order_cpu_.data());
}

void ParticleGpuBuffer::uploadLampNeighbourhoods(const ParticleSet& particles, const std::vector<Light>& lights) {
    rank_.assign(particles.size(), 0u);
    for (std::size_t r = 0; r < order_cpu_.size() && r < rank_.size(); ++r) rank_[order_cpu_[r]] = static_cast<std::uint32_t>(r);
    uploadLampNeighbourhoods(particles, lights, rank_, LampsListed::InsideMedium);
}

void ParticleGpuBuffer::uploadLampNeighbourhoods(const ParticleSet& particles, const std::vector<Light>& lights,
                                                 const std::vector<std::uint32_t>& rankOf, LampsListed which, double minimumReach) {
    lamps_.find(particles, lights, rankOf, which, minimumReach);
    lampBuffer_.upload(lamps_);
}

}  // namespace nimbus::media
