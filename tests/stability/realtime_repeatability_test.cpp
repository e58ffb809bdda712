// Repeatability of real-time frames under llvmpipe's default, multi-threaded rasteriser (its own
// executable: the other stability suites pin llvmpipe to one thread, see createContext).
//
// What could go wrong: a buffer updated mid-frame (glNamedBufferSubData) while draws queued
// earlier in the frame still have to read its old contents. GL orders the two, but llvmpipe's
// threaded rasteriser (Mesa 22.3) does not wait for queued draws that read the buffer as an SSBO,
// so the draws see a mix of old and new data, differently from run to run.
// Blocks mode rewrites its tiles buffer for every light view and then for the camera
// (block_impostor_pass.cpp BlockGpuBuffers::uploadTiles, called from block_slice_pass.cpp and
// block_composite_pass.cpp) and its draw order buffer (uploadDrawOrder) in the same frame.
// Measured (light_directions.gltf, camera "antiparallel", 96×54, six runs of `sandbox render
// --mode blocks`): rel-RMSE against the reference 1.49, 1.49, 1.49, 1.28, 1.24, 1.49, and 0.147
// every time with one rasterizer thread or with a glFinish() before each upload (a local
// experiment, not committed), which is what a correct frame gives.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "nimbus/media/reference/image_metrics.h"
#include "stability_harness.h"

namespace nimbus::stability {
namespace {

class ThreadedRepeatabilityTest : public ::testing::Test {
protected:
    static void SetUpTestSuite() { context_ = createContext(/*oneRasterizerThread=*/false); }
    static void TearDownTestSuite() { context_.reset(); }
    void SetUp() override {
        context_->makeCurrent();
        (void)context_->takeGlErrors();
    }

    // The largest rel-RMSE between the first frame and each of `frames` − 1 more of the same state.
    static double worstRepeatChange(media::MediaMode mode, int frames) {
        sandbox::Session session({sceneDirectory() / "light_directions.gltf", 0.0, {}});
        const assets::RgbImage first = renderMode(session, mode, 96, 54, "antiparallel");
        double worst = 0.0;
        for (int i = 1; i < frames; ++i) {
            const assets::RgbImage again = renderMode(session, mode, 96, 54, "antiparallel");
            worst = std::max(worst, media::reference::compareImages(again, first).relRmse);
        }
        EXPECT_EQ(context_->takeGlErrors().count, 0u);
        std::printf("[stability] threaded llvmpipe, %s: worst change over %d frames %.3g\n", media::mediaModeName(mode),
                    frames, worst);
        return worst;
    }

    static inline std::unique_ptr<gpu::Context> context_;
};

TEST_F(ThreadedRepeatabilityTest, ParticlesFramesAreIdentical) {
    EXPECT_EQ(worstRepeatChange(media::MediaMode::Particles, 8), 0.0);
}

// DISABLED (finding for blocks mode, see the top of this file): frames of the same state differ by
// up to ~60% rel-RMSE. Fix by not rewriting a buffer that queued draws still read: one tiles buffer
// per view (or all views' tiles uploaded once, bound with glBindBufferRange), and the draw order
// uploaded before the frame's first draw. Then remove the one-thread pin in createContext.
TEST_F(ThreadedRepeatabilityTest, DISABLED_BlocksFramesAreIdentical) {
    EXPECT_EQ(worstRepeatChange(media::MediaMode::Blocks, 8), 0.0);
}

}  // namespace
}  // namespace nimbus::stability
