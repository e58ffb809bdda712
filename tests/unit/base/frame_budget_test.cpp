// Tests engine/base/src/frame_budget.cpp: the budget controller walks its ladder with an injected
// clock, so every frame's duration is exactly what the test says.
#include "nimbus/base/frame_budget.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace nimbus {
namespace {

// Renders frames whose duration depends only on the rung, on a fake clock, until the controller
// settles; returns the rungs each frame used.
std::vector<int> walk(FrameBudget& budget, double& now, const std::vector<double>& msPerRung, int frames = 60) {
    std::vector<int> used;
    for (int f = 0; f < frames && !budget.settled(); ++f) {
        used.push_back(budget.rung());
        budget.beginFrame();
        now += msPerRung[static_cast<std::size_t>(budget.rung())];
        budget.endFrame();
    }
    return used;
}

TEST(FrameBudget, SettlesOnTheLowestErrorRungThatFits) {
    double now = 0.0;
    // Rung 0 (lowest error) is the slowest; costs fall along the ladder.
    const std::vector<double> ms{900.0, 320.0, 180.0, 120.0, 60.0};
    FrameBudget budget({.budgetMs = 200.0, .rungs = 5}, [&] { return now; });
    walk(budget, now, ms);
    EXPECT_TRUE(budget.settled());
    EXPECT_EQ(budget.rung(), 2);
    EXPECT_DOUBLE_EQ(budget.medianMs(2), 180.0);
}

TEST(FrameBudget, StartsAtTheFastestRungAndNeverRendersASlowFrameTwice) {
    double now = 0.0;
    const std::vector<double> ms{5000.0, 300.0, 100.0};
    FrameBudget budget({.budgetMs = 200.0, .rungs = 3}, [&] { return now; });
    const std::vector<int> used = walk(budget, now, ms);
    ASSERT_FALSE(used.empty());
    EXPECT_EQ(used.front(), 2);
    int slowFrames = 0;
    for (int r : used) slowFrames += r == 0 ? 1 : 0;
    EXPECT_EQ(slowFrames, 0);  // rung 1 already failed; rung 0 is never tried
    EXPECT_EQ(budget.rung(), 2);
}

TEST(FrameBudget, OneFrameFarOverTheBudgetCondemnsARungAtOnce) {
    double now = 0.0;
    const std::vector<double> ms{1000.0, 50.0};
    FrameBudget budget({.budgetMs = 100.0, .rungs = 2, .window = 5}, [&] { return now; });
    const std::vector<int> used = walk(budget, now, ms);
    int atRungZero = 0;
    for (int r : used) atRungZero += r == 0 ? 1 : 0;
    EXPECT_EQ(atRungZero, 1);
    EXPECT_EQ(budget.rung(), 1);
    EXPECT_TRUE(budget.settled());
}

TEST(FrameBudget, TheFastestRungIsKeptWhenNothingFits) {
    double now = 0.0;
    FrameBudget budget({.budgetMs = 10.0, .rungs = 3}, [&] { return now; });
    walk(budget, now, {300.0, 200.0, 100.0});
    EXPECT_TRUE(budget.settled());
    EXPECT_EQ(budget.rung(), 2);
}

TEST(FrameBudget, SettledStepsDownWhenFramesStopFitting) {
    double now = 0.0;
    std::vector<double> ms{500.0, 90.0, 40.0};
    FrameBudget budget({.budgetMs = 100.0, .rungs = 3}, [&] { return now; });
    walk(budget, now, ms);
    ASSERT_EQ(budget.rung(), 1);
    ms[1] = 105.0;  // within the 10 % tolerance: stays
    for (int f = 0; f < 6; ++f) budget.record(ms[static_cast<std::size_t>(budget.rung())]);
    EXPECT_EQ(budget.rung(), 1);
    ms[1] = 130.0;  // the scene grew heavier
    for (int f = 0; f < 3; ++f) budget.record(ms[static_cast<std::size_t>(budget.rung())]);
    EXPECT_EQ(budget.rung(), 2);
    EXPECT_TRUE(budget.settled());
}

TEST(FrameBudget, JudgesTheMedianNotOneSlowFrame) {
    double now = 0.0;
    FrameBudget budget({.budgetMs = 100.0, .rungs = 2}, [&] { return now; });
    ASSERT_EQ(budget.rung(), 1);
    budget.record(20.0);
    budget.record(20.0);
    budget.record(20.0);  // rung 1 fits: try rung 0
    ASSERT_EQ(budget.rung(), 0);
    budget.record(150.0);  // one noisy frame, under twice the budget
    budget.record(80.0);
    budget.record(90.0);
    EXPECT_EQ(budget.rung(), 0);
    EXPECT_TRUE(budget.settled());
}

TEST(FrameBudget, RefusesABudgetThatIsNotAPositiveNumber) {
    EXPECT_THROW(FrameBudget({.budgetMs = 0.0, .rungs = 2}), std::invalid_argument);
    EXPECT_THROW(FrameBudget({.budgetMs = -5.0, .rungs = 2}), std::invalid_argument);
    EXPECT_THROW(FrameBudget({.budgetMs = std::nan(""), .rungs = 2}), std::invalid_argument);
    EXPECT_THROW(FrameBudget({.budgetMs = 10.0, .rungs = 0}), std::invalid_argument);
}

}  // namespace
}  // namespace nimbus
