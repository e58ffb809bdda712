// Tests plugins/participating_media/core/src/blocks/block_seam_mask_pass.cpp: the seam mask's cell size.
// What the mask holds, and that block_shading=seam is exact there and smooth away from it, is
// judged on a scene (tests/scenes/blocks/cloud_blocks_test.cpp SeamShadingIsExactAtTheSeam...).
#include <gtest/gtest.h>

#include "blocks/block_seam_mask_pass.h"

namespace nimbus::media {
namespace {

TEST(SeamMaskCell, AboutA48thOfTheShorterSideAndAtLeastFourTexels) {
    EXPECT_EQ(seamMaskCell({64, 36}), 4);
    EXPECT_EQ(seamMaskCell({256, 144}), 4);  // the unseen block scenes' size
    EXPECT_EQ(seamMaskCell({320, 180}), 4);
    EXPECT_EQ(seamMaskCell({640, 360}), 8);
    EXPECT_EQ(seamMaskCell({1280, 720}), 15);
    EXPECT_EQ(seamMaskCell({1920, 1080}), 23);
    EXPECT_EQ(seamMaskCell({720, 1280}), 15) << "portrait: the shorter side decides";
    EXPECT_EQ(seamMaskCell({1, 1}), 4);
}

}  // namespace
}  // namespace nimbus::media
