// Per-pass timing (render/pass_timer.h): samples per pass name, and the median used by --stats.
#include "nimbus/gpu/pass_timer.h"

#include <gtest/gtest.h>

#include "nimbus/gpu/context.h"

namespace nimbus::gpu {
namespace {

TEST(Median, OddEvenAndEmpty) {
    EXPECT_DOUBLE_EQ(median({3.0, 1.0, 2.0}), 2.0);
    EXPECT_DOUBLE_EQ(median({4.0, 1.0, 3.0, 2.0}), 2.5);
    EXPECT_DOUBLE_EQ(median({7.0}), 7.0);
    EXPECT_DOUBLE_EQ(median({}), 0.0);
    EXPECT_DOUBLE_EQ(median({1.0, 100.0, 2.0, 3.0, 1000.0}), 3.0) << "outliers do not move it";
}

TEST(GlPassTimer, RecordsOneSamplePerPassRun) {
    auto context = gpu::Context::create();
    GlPassTimer timer;
    for (int frame = 0; frame < 3; ++frame) {
        timer.begin("shadow_maps");
        timer.end("shadow_maps");
        timer.begin("opaque");
        timer.end("opaque");
    }
    ASSERT_EQ(timer.samples().size(), 2u);
    EXPECT_EQ(timer.samples().at("shadow_maps").size(), 3u);
    EXPECT_EQ(timer.samples().at("opaque").size(), 3u);
    for (const auto& [pass, samples] : timer.samples())
        for (const double ms : samples) EXPECT_GE(ms, 0.0) << pass;
    timer.clear();
    EXPECT_TRUE(timer.samples().empty());
}

}  // namespace
}  // namespace nimbus::gpu
