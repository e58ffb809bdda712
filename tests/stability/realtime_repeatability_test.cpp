// Repeatability of real-time frames under llvmpipe's multi-threaded rasteriser: eight frames of the
// same state, in each mode, must be identical.
//
// What could go wrong: a buffer rewritten (glNamedBufferSubData) while draws queued earlier still
// have to read its old contents. GL orders the two, but llvmpipe's threaded rasteriser (Mesa 22.3)
// does not wait for queued draws that read the buffer as an SSBO, so they read a mix of old and new
// data, differently from run to run. Blocks mode used to rewrite one tiles buffer for every light
// view and again for the camera within a frame: light_directions.gltf, camera "antiparallel",
// 96×54, six runs of `sandbox render --mode blocks` gave rel-RMSE 1.49, 1.49, 1.49, 1.28, 1.24,
// 1.49 against the reference, and 0.147 every time with one rasterizer thread (LP_NUM_THREADS=0)
// or with a glFinish() before each upload.
// What prevents it: commit 640811e — every view's tiles live in ranges of one buffer written in the
// frame's upload pass, before its first draw (block_impostor_pass.cpp BlockGpuBuffers), and
// SceneRenderer waits on the previous frame's fence before rewriting per-frame buffers.
// The scene: a light straight down and the camera looking up into it (light_directions.gltf,
// "antiparallel"), where blocks mode's light slices decide nearly every pixel.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "nimbus/media/reference/image_metrics.h"
#include "stability_harness.h"

namespace nimbus::stability {
namespace {

class RepeatabilityTest : public StabilityTest {
protected:
    // The largest rel-RMSE between the first frame and each of `frames` − 1 more of the same state.
    static double worstRepeatChange(MediaMode mode, int frames) {
        sandbox::Session session({.scene = sceneDirectory() / "light_directions.gltf", .scattering = assets::Scattering::Single});
        const assets::RgbImage first = renderMode(session, mode, 96, 54, "antiparallel");
        double worst = 0.0;
        for (int i = 1; i < frames; ++i) {
            const assets::RgbImage again = renderMode(session, mode, 96, 54, "antiparallel");
            worst = std::max(worst, media::reference::compareImages(again, first).relRmse);
        }
        EXPECT_EQ(context().takeGlErrors().count, 0u);
        std::printf("[stability] %s: worst change over %d frames %.3g\n", mediaModeName(mode), frames, worst);
        return worst;
    }
};

TEST_F(RepeatabilityTest, ParticlesFramesAreIdentical) { EXPECT_EQ(worstRepeatChange(MediaMode::Particles, 8), 0.0); }

TEST_F(RepeatabilityTest, BlocksFramesAreIdentical) { EXPECT_EQ(worstRepeatChange(MediaMode::Blocks, 8), 0.0); }

}  // namespace
}  // namespace nimbus::stability
