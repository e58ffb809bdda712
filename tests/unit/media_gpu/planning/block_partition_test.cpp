// Tests plugins/participating_media/core/src/planning/block_partition.cpp: median-bisection blocks.
#include "nimbus/media/block_partition.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "block_test_clouds.h"

namespace nimbus::media {
namespace {

using test::blobCloud;

// The block each particle belongs to, by particle index.
std::vector<std::uint32_t> membership(const BlockPartition& p, std::size_t n) {
    std::vector<std::uint32_t> block(n, ~0u);
    for (std::uint32_t b = 0; b < p.blocks.size(); ++b)
        for (std::uint32_t k = 0; k < p.blocks[b].count; ++k) block[p.order[p.blocks[b].first + k]] = b;
    return block;
}

std::size_t changedMemberships(const BlockPartition& a, const BlockPartition& b, std::size_t n) {
    const auto ma = membership(a, n), mb = membership(b, n);
    std::size_t changed = 0;
    for (std::size_t i = 0; i < n; ++i) changed += ma[i] != mb[i] ? 1 : 0;
    return changed;
}

// Radius of the smallest sphere around the cloud's mean that holds every particle sphere.
double cloudRadius(const ParticleSet& set) {
    glm::dvec3 mean(0.0);
    for (const auto& p : set.position) mean += p;
    mean /= static_cast<double>(set.size());
    double r = 0.0;
    for (std::size_t i = 0; i < set.size(); ++i) r = std::max(r, glm::length(set.position[i] - mean) + set.radius[i]);
    return r;
}

void expectValidPartition(const ParticleSet& set, const BlockPartition& p, std::size_t expectedBlocks) {
    const std::size_t n = set.size();
    ASSERT_EQ(p.blocks.size(), expectedBlocks);
    ASSERT_EQ(p.order.size(), n);
    // Every particle exactly once: `order` is a permutation and the blocks tile it back to back.
    std::vector<int> seen(n, 0);
    for (std::uint32_t i : p.order) {
        ASSERT_LT(i, n);
        ++seen[i];
    }
    EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](int s) { return s == 1; }));
    std::uint32_t next = 0, smallest = ~0u, largest = 0;
    for (const Block& b : p.blocks) {
        EXPECT_EQ(b.first, next);
        next += b.count;
        smallest = std::min(smallest, b.count);
        largest = std::max(largest, b.count);
    }
    EXPECT_EQ(next, n);
    EXPECT_LE(largest - smallest, 1u) << "block sizes must differ by at most one";
    EXPECT_GE(smallest, 1u);
    // Each block's centre is its members' mean and its sphere holds every member's sphere.
    for (const Block& b : p.blocks) {
        glm::dvec3 mean(0.0);
        double radiusSum = 0.0;
        for (std::uint32_t k = 0; k < b.count; ++k) {
            const std::uint32_t i = p.order[b.first + k];
            mean += set.position[i];
            radiusSum += set.radius[i];
            EXPECT_LE(glm::length(set.position[i] - b.centre) + set.radius[i], b.radius * (1.0 + 1e-12));
        }
        mean /= static_cast<double>(b.count);
        EXPECT_LT(glm::length(mean - b.centre), 1e-9 * (1.0 + glm::length(mean)));
        EXPECT_NEAR(b.meanParticleRadius, radiusSum / b.count, 1e-5);
    }
}

TEST(BlockPartition, CostModelCountIsTwiceTheRoundedSquareRootClamped) {
    EXPECT_EQ(costModelBlockCount(0), 0);
    EXPECT_EQ(costModelBlockCount(1), 2);   // 2·1; partitionIntoBlocks never makes more blocks than particles
    EXPECT_EQ(costModelBlockCount(2), 3);   // 2·1.41 = 2.83
    EXPECT_EQ(costModelBlockCount(500), 45);  // 2·22.36 = 44.7: cloud.gltf
    EXPECT_EQ(costModelBlockCount(8000), 179);  // 2·89.4: cumulus.gltf
    EXPECT_EQ(costModelBlockCount(10000), 200);
    EXPECT_EQ(costModelBlockCount(1024 * 1024), 2048);
    EXPECT_EQ(costModelBlockCount(1025 * 1025), 2048);  // clamped
    EXPECT_EQ(costModelBlockCount(100000000), 2048);
}

TEST(BlockPartition, ThicknessIsTheMassOverTheBoundingCrossSection) {
    // One particle: its kernel mass σR³·4π∫₀¹x²e^(−4.5x²)dx = 0.5663 σR³ over πR², i.e. 0.1803 σR
    // (its optical depth through the centre is 0.833 σR: the mean over the disc is lower).
    ParticleSet one;
    one.push(glm::dvec3(1.0, 2.0, 3.0), 0.5f, 4.0f, Medium{});
    const BlockPartition p = partitionIntoBlocks(one, 1);
    EXPECT_NEAR(blockThickness(one, p, p.blocks[0]), 0.18025 * 4.0 * 0.5, 1e-4);
}

TEST(BlockPartition, AutomaticCountKeepsTheCostModelForThinMediaAndSplitsThickOnes) {
    const ParticleSet thin = blobCloud(500, 5, glm::dvec3(0.0, 4.0, 0.0), glm::dvec3(3.6, 1.8, 2.6), 0.9f, 1.5f, 0.3f);
    EXPECT_EQ(automaticBlockCount(thin), costModelBlockCount(500));
    for (const float sigma : {3.0f, 10.0f, 1000.0f}) {
        const ParticleSet thick = blobCloud(500, 5, glm::dvec3(0.0, 4.0, 0.0), glm::dvec3(3.6, 1.8, 2.6), 0.9f, 1.5f, sigma);
        const int count = automaticBlockCount(thick);
        SCOPED_TRACE("sigma " + std::to_string(sigma) + ": " + std::to_string(count) + " blocks");
        EXPECT_GT(count, costModelBlockCount(500));
        EXPECT_LE(count, 250);  // never below two particles a block
        const BlockPartition p = partitionIntoBlocks(thick, 0);
        EXPECT_EQ(p.blocks.size(), static_cast<std::size_t>(count));
        std::vector<double> thickness;
        for (const Block& b : p.blocks) thickness.push_back(blockThickness(thick, p, b));
        std::sort(thickness.begin(), thickness.end());
        if (count < 250) {
            EXPECT_LE(thickness[thickness.size() / 2], 1.5 * kMaxBlockThickness);
        }
    }
    EXPECT_EQ(automaticBlockCount(ParticleSet{}), 0);
}

TEST(BlockPartition, AutomaticCountDoublesOnceForALampInsideTheMedium) {
    // Thin (σ 0.3): the thickness bound keeps the cost model's count, so only the lamp moves it.
    const ParticleSet thin = blobCloud(500, 5, glm::dvec3(0.0, 4.0, 0.0), glm::dvec3(3.6, 1.8, 2.6), 0.9f, 1.5f, 0.3f);
    const int costModel = costModelBlockCount(500);
    const glm::dvec3 inside(0.0, 4.0, 0.0), beside(12.0, 4.0, 0.0), far(0.0, 400.0, 0.0);
    EXPECT_EQ(automaticBlockCount(thin, {inside}), 2 * costModel);
    EXPECT_EQ(automaticBlockCount(thin, {far, inside}), 2 * costModel);  // the nearest lamp counts
    EXPECT_EQ(automaticBlockCount(thin, {beside}), costModel);           // lights the cloud from outside
    EXPECT_EQ(automaticBlockCount(thin, {far}), costModel);
    EXPECT_EQ(automaticBlockCount(thin, {}), costModel);
    // Doubled once, not more, and not on top of the thickness bound's doublings.
    const ParticleSet thick = blobCloud(500, 5, glm::dvec3(0.0, 4.0, 0.0), glm::dvec3(3.6, 1.8, 2.6), 0.9f, 1.5f, 10.0f);
    EXPECT_EQ(automaticBlockCount(thick, {inside}), automaticBlockCount(thick));
    EXPECT_EQ(partitionIntoBlocks(thin, 0, {inside}).blocks.size(), static_cast<std::size_t>(2 * costModel));
    EXPECT_EQ(partitionIntoBlocks(thin, 7, {inside}).blocks.size(), 7u);  // a fixed count is kept
    std::vector<Light> lights(3);
    lights[0].position = glm::dvec3(9.0);  // directional: where its node sits means nothing
    lights[1].kind = gpu::LightKind::Point;
    lights[1].position = inside;
    lights[2].kind = gpu::LightKind::Spot;
    lights[2].position = far;
    EXPECT_EQ(lampPositions(lights), (std::vector<glm::dvec3>{inside, far}));
}

TEST(BlockPartition, LampSlicesTakeTheBlocksALampSeesWide) {
    BlockPartition p;
    p.blocks.resize(3);
    p.blocks[0].centre = glm::dvec3(0.0);
    p.blocks[0].radius = 1.0;
    p.blocks[1].centre = glm::dvec3(10.0, 0.0, 0.0);
    p.blocks[1].radius = 1.0;
    p.blocks[2].centre = glm::dvec3(0.0, 10.0, 0.0);
    p.blocks[2].radius = 3.0;
    const glm::dvec3 lamp(1.5, 0.0, 0.0);  // just outside block 0: r/d = 0.67; block 1: 0.12; block 2: 0.3
    EXPECT_EQ(blocksSeenWideFromLamps(p, {lamp}), (std::vector<std::uint8_t>{1, 0, 0}));
    EXPECT_EQ(blocksSeenWideFromLamps(p, {glm::dvec3(0.0, 14.0, 0.0)}), (std::vector<std::uint8_t>{0, 0, 1}));  // 3/4
    EXPECT_EQ(blocksSeenWideFromLamps(p, {glm::dvec3(0.0, 16.0, 0.0)}), (std::vector<std::uint8_t>{0, 0, 0}));  // 3/6: not wider
    EXPECT_EQ(blocksSeenWideFromLamps(p, {lamp, glm::dvec3(10.0, 0.0, 0.0)}), (std::vector<std::uint8_t>{1, 1, 0}));  // inside 1
    EXPECT_EQ(blocksSeenWideFromLamps(p, {}), (std::vector<std::uint8_t>{0, 0, 0}));
    EXPECT_DOUBLE_EQ(lampSpread(p.blocks[2], {glm::dvec3(0.0, 16.0, 0.0), glm::dvec3(0.0, 40.0, 0.0)}), 0.5);  // the nearest
}

TEST(BlockPartition, CoversEveryParticleOnceInNearlyEqualBlocks) {
    for (std::size_t n : {1u, 2u, 7u, 100u, 500u, 1013u}) {
        const ParticleSet set = blobCloud(n, static_cast<unsigned>(n));
        SCOPED_TRACE("n = " + std::to_string(n));
        const std::size_t automatic = std::min<std::size_t>(n, static_cast<std::size_t>(automaticBlockCount(set)));
        expectValidPartition(set, partitionIntoBlocks(set, 0), automatic);
        expectValidPartition(set, partitionIntoBlocks(set, -3), automatic);
        for (int blocks : {1, 3, 22, 64})
            expectValidPartition(set, partitionIntoBlocks(set, blocks), std::min<std::size_t>(n, static_cast<std::size_t>(blocks)));
    }
    const ParticleSet none;
    const BlockPartition empty = partitionIntoBlocks(none, 0);
    EXPECT_TRUE(empty.blocks.empty());
    EXPECT_TRUE(empty.order.empty());
}

// Largest distance of a block's member centres from the block centre (no particle radius: that is
// a floor every block pays), over the same for the whole cloud.
std::vector<double> blockSpreads(const ParticleSet& set, const BlockPartition& p) {
    glm::dvec3 mean(0.0);
    for (const auto& q : set.position) mean += q;
    mean /= static_cast<double>(set.size());
    double cloud = 0.0;
    for (const auto& q : set.position) cloud = std::max(cloud, glm::length(q - mean));
    std::vector<double> spreads;
    for (const Block& b : p.blocks) {
        double spread = 0.0;
        for (std::uint32_t k = 0; k < b.count; ++k) spread = std::max(spread, glm::length(set.position[p.order[b.first + k]] - b.centre));
        spreads.push_back(spread / cloud);
    }
    return spreads;
}

double mean(const std::vector<double>& v) {
    double s = 0.0;
    for (double x : v) s += x;
    return s / static_cast<double>(v.size());
}

// The same chunking applied to a random order: what "no spatial grouping" looks like.
BlockPartition randomSplit(const ParticleSet& set, std::size_t blocks, unsigned seed) {
    // Start from the real partition (same sizes), then shuffle who goes where.
    BlockPartition p = partitionIntoBlocks(set, static_cast<int>(blocks));
    std::shuffle(p.order.begin(), p.order.end(), std::mt19937(seed));
    for (Block& block : p.blocks) {
        block.centre = glm::dvec3(0.0);
        for (std::uint32_t k = 0; k < block.count; ++k) block.centre += set.position[p.order[block.first + k]];
        block.centre /= static_cast<double>(block.count);
    }
    return p;
}

TEST(BlockPartition, BlocksAreFarMoreCompactThanARandomSplit) {
    // Member-centre spread over the cloud's, averaged over the blocks. Measured (500 particles, 45
    // blocks, seeds 5–7): median bisection 0.27, a random split 0.84–0.88. (Morton chunks, the first
    // partition, gave 0.51–0.53 with 22 blocks.)
    for (unsigned seed : {5u, 6u, 7u}) {
        const ParticleSet set = blobCloud(500, seed);
        const BlockPartition p = partitionIntoBlocks(set, 0);
        const double spread = mean(blockSpreads(set, p));
        const double random = mean(blockSpreads(set, randomSplit(set, p.blocks.size(), seed)));
        EXPECT_LT(spread, 0.65 * random) << "seed " << seed << ": blocks " << spread << ", random " << random;
        EXPECT_LT(spread, 0.4) << "seed " << seed;
    }
}

// Morton chunks of equal size (the first partition) failed this: they straddle the jumps of the
// Z-order curve, and one block of 22 held members from both ends of the cloud (bounding radius
// 1.32× the cloud's). A block whose impostor spans the cloud has the whole cloud's [front, back]
// interval, which defeats the uniform-density scaling of Umenhoffer and Szirmay-Kalos §2.4.
TEST(BlockPartition, EveryBlocksBoundingRadiusIsWellBelowTheClouds) {
    for (unsigned seed : {5u, 6u, 7u}) {
        const ParticleSet set = blobCloud(500, seed);
        const BlockPartition p = partitionIntoBlocks(set, 0);
        const double cloud = cloudRadius(set);
        for (std::size_t b = 0; b < p.blocks.size(); ++b)
            EXPECT_LT(p.blocks[b].radius, 0.75 * cloud) << "seed " << seed << " block " << b << ": "
                                                         << p.blocks[b].radius / cloud << " of the cloud's radius";
    }
}

TEST(BlockPartition, IsDeterministic) {
    const ParticleSet set = blobCloud(800, 9);
    const BlockPartition a = partitionIntoBlocks(set, 0), b = partitionIntoBlocks(set, 0);
    EXPECT_EQ(a.order, b.order);
    ASSERT_EQ(a.blocks.size(), b.blocks.size());
    for (std::size_t i = 0; i < a.blocks.size(); ++i) {
        EXPECT_EQ(a.blocks[i].first, b.blocks[i].first);
        EXPECT_EQ(a.blocks[i].count, b.blocks[i].count);
        EXPECT_EQ(a.blocks[i].centre, b.blocks[i].centre);
        EXPECT_EQ(a.blocks[i].radius, b.blocks[i].radius);
    }
}

TEST(BlockPartition, StableUnderASmallTranslationOfEveryParticle) {
    // Median bisection depends only on the particles' relative order along the axes, which a common
    // translation does not change (up to rounding of the positions).
    const ParticleSet set = blobCloud(500, 5);
    const BlockPartition before = partitionIntoBlocks(set, 0);
    for (const glm::dvec3 shift : {glm::dvec3(0.02, 0.0, 0.0), glm::dvec3(0.013, -0.017, 0.011)}) {
        ParticleSet moved = set;
        for (auto& p : moved.position) p += shift;
        const std::size_t changed = changedMemberships(before, partitionIntoBlocks(moved, 0), set.size());
        EXPECT_LE(changed, set.size() / 10) << "most memberships must survive a 2 cm shift";
    }
}

TEST(BlockPartition, MovingOneParticleChangesFewMemberships) {
    // One particle crossing a split plane makes that split hand one particle back the other way, and
    // so on down the tree: a few changes per level, at most blocks + 1 in all. The exception: when
    // the moved particle grows a subtree's bounding box enough to change its longest axis, that
    // subtree is split along another axis and reshuffled. Measured (500 particles, 45 blocks, 20
    // trials): 19 trials within blocks + 1, one at 86 memberships (17%). A random split would change
    // ~98%. The count is pinned to that measurement's: the automatic count gives this cloud 90 (its
    // thickness), where 3 of the 20 trials change the axis; the test below keeps the count itself.
    const ParticleSet set = blobCloud(500, 5);
    const int blocks = costModelBlockCount(set.size());
    const BlockPartition before = partitionIntoBlocks(set, blocks);
    std::mt19937 rng(17);
    std::uniform_int_distribution<std::size_t> pick(0, set.size() - 1);
    int beyondTheTreeBound = 0;
    for (int trial = 0; trial < 20; ++trial) {
        ParticleSet moved = set;
        const std::size_t i = pick(rng);
        moved.position[i] = set.position[pick(rng)] + glm::dvec3(0.3, -0.2, 0.1);
        const std::size_t changed = changedMemberships(before, partitionIntoBlocks(moved, blocks), set.size());
        beyondTheTreeBound += changed > before.blocks.size() + 1 ? 1 : 0;
        EXPECT_LE(changed, set.size() / 4) << "trial " << trial;
    }
    EXPECT_LE(beyondTheTreeBound, 2) << "an axis change should be the exception";
    // A small nudge of one particle changes little.
    ParticleSet nudged = set;
    nudged.position[123] += glm::dvec3(0.05, 0.0, 0.0);
    EXPECT_LE(changedMemberships(before, partitionIntoBlocks(nudged, blocks), set.size()), 3u);
}

TEST(BlockPartition, AutomaticCountDoesNotChangeWhenOneParticleMoves) {
    // The count steps in powers of two of the cost model's: a count that followed the median
    // thickness smoothly would change with almost any move, and a new count reshuffles every block.
    const ParticleSet set = blobCloud(500, 5);
    const int count = automaticBlockCount(set);
    ASSERT_GT(count, costModelBlockCount(set.size()));  // a thick cloud: the case where it could move
    std::mt19937 rng(17);
    std::uniform_int_distribution<std::size_t> pick(0, set.size() - 1);
    for (int trial = 0; trial < 20; ++trial) {
        ParticleSet moved = set;
        moved.position[pick(rng)] = set.position[pick(rng)] + glm::dvec3(0.3, -0.2, 0.1);
        EXPECT_EQ(automaticBlockCount(moved), count) << "trial " << trial;
    }
}

TEST(BlockPartition, FarFromTheOriginBlocksStayCompactAndValid) {
    // Positions are double and the splits compare them exactly, so a cloud 1e5 m away splits like
    // one at the origin.
    const ParticleSet near = blobCloud(500, 5);
    ParticleSet far = near;
    for (auto& p : far.position) p += glm::dvec3(1.0e5, 250.0, -1.0e5);
    const BlockPartition p = partitionIntoBlocks(far, 0);
    expectValidPartition(far, p, static_cast<std::size_t>(automaticBlockCount(far)));
    EXPECT_NEAR(mean(blockSpreads(far, p)), mean(blockSpreads(near, partitionIntoBlocks(near, 0))), 0.1);
}

TEST(OverlappingBlockLists, OverlappingSpheresNearestFirstWithTheirRanks) {
    BlockPartition partition;
    const auto add = [&](const glm::dvec3& centre, double radius) {
        Block b;
        b.centre = centre;
        b.radius = radius;
        b.count = 1;
        partition.blocks.push_back(b);
    };
    add(glm::dvec3(0.0), 1.0);
    add(glm::dvec3(1.8, 0.0, 0.0), 1.0);  // overlaps block 0
    add(glm::dvec3(0.0, 1.0, 0.0), 0.5);  // overlaps block 0, nearer than block 1; not block 1 (2.06 m apart)
    add(glm::dvec3(9.0, 0.0, 0.0), 1.0);  // alone
    const std::vector<std::uint32_t> backToFront{3, 1, 0, 2};
    const std::vector<glm::uvec2> lists = overlappingBlockLists(partition, backToFront);
    ASSERT_GE(lists.size(), 4u);
    const auto entries = [&](std::uint32_t b) {
        return std::vector<glm::uvec2>(lists.begin() + lists[b].x, lists.begin() + lists[b].x + lists[b].y);
    };
    EXPECT_EQ(entries(0), (std::vector<glm::uvec2>{{2u, 3u}, {1u, 1u}})) << "(block, rank), nearest first";
    EXPECT_EQ(entries(1), (std::vector<glm::uvec2>{{0u, 2u}}));
    EXPECT_EQ(entries(2), (std::vector<glm::uvec2>{{0u, 2u}}));
    EXPECT_TRUE(entries(3).empty());
}

TEST(OverlappingBlockLists, KeepsTheNearestWhenMoreOverlap) {
    BlockPartition partition;
    for (std::size_t k = 0; k <= kMaxOrderNeighbours + 4; ++k) {
        Block b;
        b.centre = glm::dvec3(0.01 * static_cast<double>(k), 0.0, 0.0);
        b.radius = 1.0;
        b.count = 1;
        partition.blocks.push_back(b);
    }
    std::vector<std::uint32_t> order(partition.blocks.size());
    for (std::uint32_t k = 0; k < order.size(); ++k) order[k] = k;
    const std::vector<glm::uvec2> lists = overlappingBlockLists(partition, order);
    EXPECT_EQ(lists[0].y, kMaxOrderNeighbours);
    for (std::uint32_t k = 0; k < kMaxOrderNeighbours; ++k) EXPECT_EQ(lists[lists[0].x + k].x, k + 1) << "block 0's nearest, in order";
}

}  // namespace
}  // namespace nimbus::media
