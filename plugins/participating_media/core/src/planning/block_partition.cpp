#include "nimbus/media/block_partition.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "nimbus/media/optics.h"

namespace nimbus::media {
namespace {

// Splits order[p(b0), p(b1)) into blocks b0..b1-1, where p(b) = floor(b·n/K) is where block b
// starts: the same split points whatever the recursion, so sizes differ by at most one.
void bisect(const ParticleSet& particles, std::vector<std::uint32_t>& order, std::size_t b0, std::size_t b1, std::size_t count,
            std::size_t blocks) {
    if (b1 - b0 <= 1) return;
    auto start = [&](std::size_t b) { return b * count / blocks; };
    const auto first = order.begin() + static_cast<std::ptrdiff_t>(start(b0));
    const auto last = order.begin() + static_cast<std::ptrdiff_t>(start(b1));
    glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
    for (auto it = first; it != last; ++it) {
        lo = glm::min(lo, particles.position[*it]);
        hi = glm::max(hi, particles.position[*it]);
    }
    const glm::dvec3 extent = hi - lo;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
    const std::size_t bm = (b0 + b1) / 2;
    const auto middle = order.begin() + static_cast<std::ptrdiff_t>(start(bm));
    std::nth_element(first, middle, last, [&](std::uint32_t a, std::uint32_t b) {
        const double pa = particles.position[a][axis], pb = particles.position[b][axis];
        return pa < pb || (pa == pb && a < b);
    });
    bisect(particles, order, b0, bm, count, blocks);
    bisect(particles, order, bm, b1, count, blocks);
}

}  // namespace

std::vector<glm::dvec3> lampPositions(const std::vector<Light>& lights) {
    std::vector<glm::dvec3> lamps;
    for (const Light& light : lights)
        if (light.kind != gpu::LightKind::Directional) lamps.push_back(light.position);
    return lamps;
}

int costModelBlockCount(std::size_t particles) {
    if (particles == 0) return 0;
    return std::clamp(static_cast<int>(std::lround(2.0 * std::sqrt(static_cast<double>(particles)))), 1, kMaxBlocks);
}

double blockThickness(const ParticleSet& particles, const BlockPartition& partition, const Block& block) {
    // ∫ exp(−4.5 r²/R²) dV over the ball of radius R, per R³: 4π ∫₀¹ x² e^(−a x²) dx, a = 4.5.
    static const double massPerR3 = [] {
        const double a = kKernelFalloff;
        return 4.0 * kPi * (std::sqrt(kPi) * std::erf(std::sqrt(a)) / (4.0 * a * std::sqrt(a)) - std::exp(-a) / (2.0 * a));
    }();
    double mass = 0.0;
    for (std::uint32_t k = block.first; k < block.first + block.count; ++k) {
        const std::uint32_t i = partition.order[k];
        const double r = particles.radius[i];
        mass += massPerR3 * particles.sigma[i] * r * r * r;
    }
    return block.radius > 0.0 ? mass / (kPi * block.radius * block.radius) : 0.0;
}

double lampSpread(const Block& block, const std::vector<glm::dvec3>& lamps) {
    double spread = 0.0;
    for (const glm::dvec3& lamp : lamps)
        spread = std::max(spread, block.radius / std::max(glm::length(lamp - block.centre), 1e-9 * block.radius));
    return spread;
}

std::vector<std::uint8_t> blocksSeenWideFromLamps(const BlockPartition& partition, const std::vector<glm::dvec3>& lamps) {
    std::vector<std::uint8_t> wide(partition.blocks.size(), 0);
    for (std::size_t b = 0; b < wide.size(); ++b) wide[b] = lampSpread(partition.blocks[b], lamps) > kMaxLampImpostorSpread ? 1 : 0;
    return wide;
}

std::vector<glm::uvec2> overlappingBlockLists(const BlockPartition& partition, const std::vector<std::uint32_t>& backToFront) {
    const std::size_t count = partition.blocks.size();
    std::vector<std::uint32_t> rank(count, 0u);
    for (std::size_t r = 0; r < backToFront.size(); ++r) rank[backToFront[r]] = static_cast<std::uint32_t>(r);
    std::vector<glm::uvec2> lists(count, glm::uvec2(0u));
    std::vector<std::pair<double, std::uint32_t>> near;
    for (std::size_t b = 0; b < count; ++b) {
        const Block& block = partition.blocks[b];
        near.clear();
        for (std::size_t n = 0; n < count; ++n) {
            const Block& other = partition.blocks[n];
            const double distance = glm::length(other.centre - block.centre);
            if (n != b && other.count > 0 && distance < block.radius + other.radius) near.emplace_back(distance, static_cast<std::uint32_t>(n));
        }
        const std::size_t kept = std::min(near.size(), kMaxOrderNeighbours);
        std::partial_sort(near.begin(), near.begin() + static_cast<std::ptrdiff_t>(kept), near.end());
        lists[b] = glm::uvec2(static_cast<std::uint32_t>(lists.size()), static_cast<std::uint32_t>(kept));
        for (std::size_t k = 0; k < kept; ++k) lists.emplace_back(near[k].second, rank[near[k].second]);
    }
    return lists;
}

namespace {

double median(std::vector<double> values) {
    const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
    std::nth_element(values.begin(), middle, values.end());
    return *middle;
}

// The count the bounds ask for, given the partition at the cost model's count.
int countForBounds(const ParticleSet& particles, const BlockPartition& costModelPartition, const std::vector<glm::dvec3>& lamps) {
    const std::size_t n = particles.size();
    const int costModel = static_cast<int>(costModelPartition.blocks.size());
    std::vector<double> thickness, spread;
    thickness.reserve(costModelPartition.blocks.size());
    spread.reserve(costModelPartition.blocks.size());
    for (const Block& block : costModelPartition.blocks) {
        thickness.push_back(blockThickness(particles, costModelPartition, block));
        spread.push_back(lampSpread(block, lamps));
    }
    int doublings = 0;
    if (const double medianThickness = median(thickness); medianThickness > kMaxBlockThickness) {
        // A block's thickness grows as the cube root of its member count in a medium of even density,
        // so the count wants (median / limit)³ times more blocks; in powers of two, so that a particle
        // moving from one frame to the next does not change the count and with it every membership.
        doublings = std::min(20, static_cast<int>(std::lround(3.0 * std::log2(medianThickness / kMaxBlockThickness))));
    }
    if (median(spread) > kMaxLampSpread) doublings = std::max(doublings, 1);
    if (doublings <= 0) return costModel;
    const int ceiling = std::max(costModel, std::min(kMaxBlocks, static_cast<int>(n / 2)));
    return static_cast<int>(std::min<long long>(static_cast<long long>(costModel) << doublings, ceiling));
}

}  // namespace

int automaticBlockCount(const ParticleSet& particles, const std::vector<glm::dvec3>& lamps) {
    return static_cast<int>(partitionIntoBlocks(particles, 0, lamps).blocks.size());
}

BlockPartition partitionIntoBlocks(const ParticleSet& particles, int blockCount, const std::vector<glm::dvec3>& lamps) {
    BlockPartition out;
    const std::size_t n = particles.size();
    if (n == 0) return out;
    if (blockCount <= 0) {
        // Automatic: the cost model's partition is measured, and kept where it is thin enough.
        BlockPartition costModel = partitionIntoBlocks(particles, costModelBlockCount(n));
        if (n < 2) return costModel;
        const int count = countForBounds(particles, costModel, lamps);
        return static_cast<std::size_t>(count) == costModel.blocks.size() ? costModel : partitionIntoBlocks(particles, count);
    }
    const std::size_t blocks = std::min<std::size_t>(n, static_cast<std::size_t>(blockCount));
    out.order.resize(n);
    std::iota(out.order.begin(), out.order.end(), 0u);
    bisect(particles, out.order, 0, blocks, n, blocks);

    out.blocks.resize(blocks);
    for (std::size_t b = 0; b < blocks; ++b) {
        const std::size_t first = b * n / blocks, last = (b + 1) * n / blocks;
        Block& block = out.blocks[b];
        block.first = static_cast<std::uint32_t>(first);
        block.count = static_cast<std::uint32_t>(last - first);
        // Members in index order inside a block: the order nth_element left them in is an artefact.
        std::sort(out.order.begin() + static_cast<std::ptrdiff_t>(first), out.order.begin() + static_cast<std::ptrdiff_t>(last));
        glm::dvec3 sum(0.0);
        for (std::size_t k = first; k < last; ++k) sum += particles.position[out.order[k]];
        block.centre = sum / static_cast<double>(last - first);
        double radiusSum = 0.0;
        for (std::size_t k = first; k < last; ++k) {
            const std::uint32_t i = out.order[k];
            block.radius = std::max(block.radius, glm::length(particles.position[i] - block.centre) + particles.radius[i]);
            radiusSum += particles.radius[i];
        }
        block.meanParticleRadius = static_cast<float>(radiusSum / static_cast<double>(last - first));
    }
    return out;
}

}  // namespace nimbus::media
