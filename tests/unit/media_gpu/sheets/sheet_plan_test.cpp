// Where sheets mode's sheets lie (sheets/sheet_plan.h): planes from the medium's near side (or the
// near plane) to its far side at the asked spacing, back to front, each drawing exactly the run of
// ranks whose spheres can reach into it; at most kMaxSheets; moved smoothly with the medium.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "sheets/sheet_plan.h"

namespace nimbus::media {
namespace {

// Centres at these view depths, farthest first, as ParticleGpuBuffer::rankDepths gives them.
const std::vector<float> kDepths = {9.0f, 8.5f, 7.2f, 7.0f, 6.1f, 5.0f, 4.4f, 3.0f};
constexpr float kRadius = 0.5f;

TEST(SheetPlan, TheSpacingIsTheMedianRadiusTimesTheTiersFactor) {
    std::vector<float> scratch;
    EXPECT_DOUBLE_EQ(sheetSpacingFor({0.1f, 2.0f, 0.4f, 0.3f, 0.2f}, 0.5, scratch), 0.5 * 0.3f);
    EXPECT_DOUBLE_EQ(sheetSpacingFor({1.0f}, 0.25, scratch), 0.25);
}

TEST(SheetPlan, SheetsSpanTheMediumBackToFrontAtTheSpacing) {
    const SheetPlan plan = planSheets(kDepths, kRadius, 2.5, 9.5, 0.1, 0.5);
    ASSERT_FALSE(plan.sheets.empty());
    EXPECT_FALSE(plan.widened);
    EXPECT_FLOAT_EQ(plan.spacing, 0.5f);
    EXPECT_FLOAT_EQ(plan.sheets.front().farDepth, 9.5f);
    EXPECT_FLOAT_EQ(plan.sheets.back().nearDepth, 2.5f);
    for (std::size_t k = 0; k < plan.sheets.size(); ++k) {
        const Sheet& s = plan.sheets[k];
        EXPECT_NEAR(s.farDepth - s.nearDepth, 0.5f, 1e-5f);
        if (k > 0) {
            EXPECT_LE(s.farDepth, plan.sheets[k - 1].nearDepth + 1e-5f) << "back to front";
        }
        // Exactly the particles whose sphere overlaps the sheet (all of radius kRadius here).
        for (std::uint32_t r = 0; r < kDepths.size(); ++r) {
            const bool overlaps = kDepths[r] + kRadius > s.nearDepth && kDepths[r] - kRadius < s.farDepth;
            const bool drawn = r >= s.firstRank && r < s.firstRank + s.ranks;
            EXPECT_EQ(drawn, overlaps) << "rank " << r << " in sheet [" << s.nearDepth << ", " << s.farDepth << "]";
        }
    }
}

TEST(SheetPlan, EmptySheetsAreLeftOut) {
    // Two particles 6 m apart: of the 14 sheets between them only the two each one crosses hold anything.
    const SheetPlan plan = planSheets({9.0f, 3.0f}, kRadius, 2.5, 9.5, 0.1, 0.5);
    ASSERT_EQ(plan.sheets.size(), 4u);
    for (const Sheet& s : plan.sheets) EXPECT_EQ(s.ranks, 1u);
}

TEST(SheetPlan, TheNearPlaneCutsTheFirstSheet) {
    const SheetPlan plan = planSheets(kDepths, kRadius, -1.0, 9.5, 4.0, 0.5);
    ASSERT_FALSE(plan.sheets.empty());
    EXPECT_FLOAT_EQ(plan.sheets.back().nearDepth, 4.0f);
    EXPECT_TRUE(planSheets(kDepths, kRadius, -3.0, -1.0, 0.1, 0.5).sheets.empty()) << "a medium behind the camera";
    EXPECT_TRUE(planSheets({}, kRadius, 1.0, 2.0, 0.1, 0.5).sheets.empty());
}

TEST(SheetPlan, TooManySheetsWidenTheSpacing) {
    const SheetPlan plan = planSheets(kDepths, kRadius, 2.5, 9.5, 0.1, 0.001);
    EXPECT_TRUE(plan.widened);
    EXPECT_NEAR(plan.spacing, 7.0f / kMaxSheets, 1e-6f);
    EXPECT_LE(plan.sheets.size(), static_cast<std::size_t>(kMaxSheets));
}

// The planes follow the medium's near side: moved by ε, every plane moves by ε, none jumps.
TEST(SheetPlan, ThePlanesMoveWithTheMediumSmoothly) {
    const SheetPlan a = planSheets(kDepths, kRadius, 2.5, 9.5, 0.1, 0.5);
    const SheetPlan b = planSheets(kDepths, kRadius, 2.5001, 9.5001, 0.1, 0.5);
    ASSERT_EQ(a.sheets.size(), b.sheets.size());
    for (std::size_t k = 0; k < a.sheets.size(); ++k) EXPECT_NEAR(b.sheets[k].nearDepth - a.sheets[k].nearDepth, 1e-4f, 1e-5f);
}

}  // namespace
}  // namespace nimbus::media
