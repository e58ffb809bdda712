// particles/particle_splat_pass.cpp: splatRuns, the runs of the draw order the splats draw with and
// without the mesh-crossing variant, the fragment lamps and the depth fetch, and the exact program's
// runs of the particles a mesh lies inside.
#include <gtest/gtest.h>

#include "particles/particle_splat_pass.h"

namespace nimbus::media {
namespace {

std::vector<std::uint32_t> identity(std::uint32_t n) {
    std::vector<std::uint32_t> order(n);
    for (std::uint32_t i = 0; i < n; ++i) order[i] = i;
    return order;
}

TEST(SplatRuns, FollowTheDrawOrderNotTheParticleIndex) {
    // Particle 0 is near a mesh and drawn last.
    const auto runs = splatRuns({2, 1, 0}, {1, 0, 0}, 1);
    ASSERT_EQ(runs.size(), 2u);
    EXPECT_EQ(runs[0].first, 0u);
    EXPECT_EQ(runs[0].count, 2u);
    EXPECT_FALSE(runs[0].meshCrossings);
    EXPECT_EQ(runs[1].first, 2u);
    EXPECT_EQ(runs[1].count, 1u);
    EXPECT_TRUE(runs[1].meshCrossings);
}

TEST(SplatRuns, ShortGapsJoinTheirNeighboursButNotTheEnds) {
    // near: ranks 2..3 and 6, plain gaps 0..1 (an end), 4..5 (short) and 7..9 (an end).
    std::vector<std::uint8_t> near(10, 0);
    near[2] = near[3] = near[6] = 1;
    const auto runs = splatRuns(identity(10), near, 4);
    ASSERT_EQ(runs.size(), 3u);
    EXPECT_FALSE(runs[0].meshCrossings);
    EXPECT_EQ(runs[0].count, 2u);
    EXPECT_TRUE(runs[1].meshCrossings);
    EXPECT_EQ(runs[1].first, 2u);
    EXPECT_EQ(runs[1].count, 5u) << "ranks 2..6, the gap 4..5 drawn with the crossing variant";
    EXPECT_FALSE(runs[2].meshCrossings);
    EXPECT_EQ(runs[2].first, 7u);
    EXPECT_EQ(runs[2].count, 3u);
}

TEST(SplatRuns, EveryRankIsDrawnOnce) {
    std::vector<std::uint8_t> near(100, 0);
    for (std::size_t i = 0; i < near.size(); i += 7) near[i] = 1;
    std::uint32_t next = 0;
    for (const SplatRun& run : splatRuns(identity(100), near)) {
        EXPECT_EQ(run.first, next);
        next += run.count;
    }
    EXPECT_EQ(next, 100u);
    EXPECT_TRUE(splatRuns({}, {}).empty());
}

TEST(SplatRuns, TheLampBitSplitsRunsAndNeverJoins) {
    // A particle drawn without the lamps has them in its fit: drawing it with them would count them twice.
    constexpr std::uint8_t both = kSplatNearMesh | kSplatNearLamp;
    const auto runs = splatRuns(identity(3), {both, kSplatNearMesh, both}, 8);
    ASSERT_EQ(runs.size(), 3u);
    EXPECT_TRUE(runs[0].lamps);
    EXPECT_FALSE(runs[1].lamps);
    EXPECT_TRUE(runs[1].meshCrossings);
    EXPECT_TRUE(runs[2].lamps);
    // A short gap without the mesh bit joins its crossing neighbours when its lamp bit is theirs.
    const auto joined = splatRuns(identity(3), {both, kSplatNearLamp, both}, 8);
    ASSERT_EQ(joined.size(), 1u);
    EXPECT_TRUE(joined[0].meshCrossings);
    EXPECT_TRUE(joined[0].lamps);
    const auto apart = splatRuns(identity(3), {both, 0, both}, 8);
    EXPECT_EQ(apart.size(), 3u) << "a gap without the lamps stays apart";
}

TEST(SplatRuns, AShortRunClearOfMeshesJoinsTheFetchingNeighboursButNeverTheOtherWay) {
    constexpr std::uint8_t clear = kSplatClearOfMeshes;
    // The depth fetch clips any particle, so a short clear gap is drawn with it.
    const auto joined = splatRuns(identity(3), {0, clear, 0}, 8);
    ASSERT_EQ(joined.size(), 1u);
    EXPECT_FALSE(joined[0].depthTested);
    // A particle near a mesh needs its fetch.
    const auto apart = splatRuns(identity(3), {clear, 0, clear}, 8);
    ASSERT_EQ(apart.size(), 3u);
    EXPECT_TRUE(apart[0].depthTested);
    EXPECT_FALSE(apart[1].depthTested);
    // Masked out (no depth test in the pass), every run fetches.
    const auto masked = splatRuns(identity(3), {clear, 0, clear}, 8, static_cast<std::uint8_t>(~clear));
    ASSERT_EQ(masked.size(), 1u);
    EXPECT_FALSE(masked[0].depthTested);
}

// A particle a mesh lies inside is drawn in runs of its own (the exact program, and where the pass
// tests depth its own fit variant as well): no run of another kind takes it in or joins across it,
// and its lamp bit still splits its runs (its fit left the lamps out).
TEST(SplatRuns, AMeshInsideIsDrawnInRunsOfItsOwn) {
    constexpr std::uint8_t inside = kSplatMeshInside, near = kSplatNearMesh;
    const auto runs = splatRuns(identity(7), {near, inside | near, inside, inside | near, inside | kSplatNearLamp, near, inside}, 8);
    ASSERT_EQ(runs.size(), 5u);
    EXPECT_FALSE(runs[0].meshInside);
    EXPECT_TRUE(runs[1].meshInside);
    EXPECT_EQ(runs[1].first, 1u);
    EXPECT_EQ(runs[1].count, 3u) << "the crossing variant takes a particle no mesh crosses";
    EXPECT_TRUE(runs[1].meshCrossings);
    EXPECT_TRUE(runs[2].meshInside && runs[2].lamps);
    EXPECT_FALSE(runs[3].meshInside) << "a short gap between two runs of particles a mesh lies inside stays apart";
    EXPECT_TRUE(runs[4].meshInside);
    const auto between = splatRuns(identity(3), {near, inside, near}, 8);
    ASSERT_EQ(between.size(), 3u) << "the crossing variant does not take a particle a mesh lies inside";
    EXPECT_TRUE(between[1].meshInside);
    const auto clear = splatRuns(identity(1), {inside | kSplatClearOfMeshes}, 8);
    ASSERT_EQ(clear.size(), 1u);
    EXPECT_FALSE(clear[0].depthTested) << "a sphere that reaches a box is never clipped by the depth test alone";
}

}  // namespace
}  // namespace nimbus::media
