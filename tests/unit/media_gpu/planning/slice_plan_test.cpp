// slice_plan.cpp: which slabs the deposit form of the slices draws a particle into, the pieces it
// packs, and the automatic slice resolution.
#include "nimbus/media/slice_plan.h"

#include <gtest/gtest.h>

#include <set>

namespace nimbus::media {
namespace {

TEST(ParticleSlabs, ASphereInsideOneSlabTouchesOnlyIt) {
    // Slabs of 1 m over [0, 8]: a sphere of radius 0.2 centred at 2.5 lies in slab 2.
    const SlabRange r = particleSlabs(2.5, 0.2, false, 0.0, 8.0, 8);
    EXPECT_EQ(r.first, 2);
    EXPECT_EQ(r.last, 2);
}

TEST(ParticleSlabs, ASphereAcrossPlanesTouchesEverySlabItReaches) {
    const SlabRange r = particleSlabs(4.0, 1.5, false, 0.0, 8.0, 8);
    EXPECT_EQ(r.first, 2);
    EXPECT_EQ(r.last, 5);
}

TEST(ParticleSlabs, DepthsOutsideTheRangeLandInTheEndSlabs) {
    // The first slab reaches back to the light, the last past the medium: no optical depth is lost.
    EXPECT_EQ(particleSlabs(-3.0, 0.5, false, 0.0, 8.0, 8).first, 0);
    EXPECT_EQ(particleSlabs(-3.0, 0.5, false, 0.0, 8.0, 8).last, 0);
    EXPECT_EQ(particleSlabs(20.0, 0.5, false, 0.0, 8.0, 8).first, 7);
    EXPECT_EQ(particleSlabs(20.0, 0.5, false, 0.0, 8.0, 8).last, 7);
}

TEST(ParticleSlabs, APerspectiveViewSkipsSpheresBehindTheLight) {
    EXPECT_LT(particleSlabs(-1.0, 0.5, true, 0.1, 8.0, 8).last, particleSlabs(-1.0, 0.5, true, 0.1, 8.0, 8).first);
    // One that reaches around the lamp is drawn from the first slab.
    EXPECT_EQ(particleSlabs(-0.2, 0.5, true, 0.1, 8.0, 8).first, 0);
}

TEST(SlabPieces, PackParticleAndSlabInParticleOrder) {
    ParticleSet particles;
    const Medium medium;
    particles.push({0.0, 0.0, -2.5}, 0.2f, 1.0f, medium);  // slab 2
    particles.push({0.0, 0.0, -4.0}, 1.5f, 1.0f, medium);  // slabs 2..5
    gpu::LightView view;  // identity: the light looks down −Z from the origin
    view.depthNear = 0.0f;
    view.depthFar = 8.0f;
    std::vector<std::uint32_t> pieces;
    appendSlabPieces(particles, view, glm::dvec3(0.0), 8, pieces);
    const std::vector<std::uint32_t> expected = {0u << kSlabBits | 2u, 1u << kSlabBits | 2u, 1u << kSlabBits | 3u,
                                                 1u << kSlabBits | 4u, 1u << kSlabBits | 5u};
    EXPECT_EQ(pieces, expected);
}

TEST(SlabPieces, FarFromTheOriginDepthsStayExact) {
    // The frame origin is subtracted in double before the view transform: 10⁷ m away, the same pieces.
    ParticleSet particles;
    particles.push({1e7, 0.0, 1e7 - 2.5}, 0.2f, 1.0f, Medium{});
    gpu::LightView view;
    view.depthNear = 0.0f;
    view.depthFar = 8.0f;
    std::vector<std::uint32_t> pieces;
    appendSlabPieces(particles, view, glm::dvec3(1e7, 0.0, 1e7), 8, pieces);
    EXPECT_EQ(pieces, std::vector<std::uint32_t>{2u});
}

TEST(SliceResolution, PutsTheAskedTexelsAcrossTheMedianRadius) {
    gpu::LightView view;
    view.halfExtent = glm::vec2(10.0f, 6.0f);  // 20 m across the larger side
    SliceEstimate estimate;
    estimate.medianSpan = 1.0;  // 1 m particles
    // 20 m / 1 m × 3 texels = 60 → the next multiple of 16.
    EXPECT_EQ(sliceResolutionFor(estimate, view, 3.0), 64);
    EXPECT_EQ(sliceResolutionFor(estimate, view, 0.25), 32) << "at least 32";
    EXPECT_EQ(sliceResolutionFor(estimate, view, 0.25, 16), 16) << "at least the minimum asked for (a lamp's own views)";
    EXPECT_EQ(sliceResolutionFor(estimate, view, 16.0), 256) << "at most the fixed default";
    estimate.medianSpan = 0.0;
    EXPECT_EQ(sliceResolutionFor(estimate, view, 3.0), 256) << "no particles seen: the fixed default";
    std::set<int> seen;
    for (double detail = 0.25; detail <= 16.0; detail *= 1.5) {
        estimate.medianSpan = 1.0;
        const int r = sliceResolutionFor(estimate, view, detail);
        EXPECT_EQ(r % 16, 0);
        seen.insert(r);
    }
    EXPECT_GT(seen.size(), 3u);
}

}  // namespace
}  // namespace nimbus::media
