// Tests plugins/participating_media/core/src/medium/volume.cpp: chords, extinction and optical depth
// of constant and noise volumes.
#include "nimbus/media/volume.h"

#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace nimbus::media {
namespace {

Medium mediumOf(float sigma) {
    Medium m;
    m.extinction = sigma;
    return m;
}

Volume noiseVolume(double time = 0.0) {
    VolumeDesc desc{.shape = VolumeShape::Ellipsoid, .size = {4.0, 2.0, 3.0}};
    desc.noise = NoiseField{.kind = NoiseKind::Value, .octaves = 4, .frequency = 0.8, .seed = 11, .coverage = 0.35, .falloff = 0.3,
                            .velocity = {0.6, 0.0, 0.2}};
    const glm::dmat4 world = glm::rotate(glm::translate(glm::dmat4(1.0), glm::dvec3(1e5, 2.0, -3.0)), 0.4, glm::dvec3(0.0, 1.0, 0.0));
    return makeVolume(desc, world, mediumOf(3.0f), "test", time);
}

TEST(Volume, ConstantOpticalDepthIsSigmaTimesTheChord) {
    const Volume box = makeVolume(VolumeShape::Box, glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, 0.0, -5.0)), {2.0, 2.0, 2.0}, mediumOf(0.7f));
    EXPECT_DOUBLE_EQ(volumeOpticalDepth(box, glm::dvec3(0.0), {0.0, 0.0, -1.0}, 0.0, 100.0), double{0.7f} * 2.0);
    EXPECT_DOUBLE_EQ(volumeOpticalDepth(box, glm::dvec3(0.0), {0.0, 0.0, -1.0}, 0.0, 5.0), double{0.7f} * 1.0);  // clipped at t1
    EXPECT_EQ(volumeOpticalDepth(box, glm::dvec3(0.0), {0.0, 1.0, 0.0}, 0.0, 100.0), 0.0);
    EXPECT_EQ(volumeExtinction(box, {0.0, 0.0, -5.5}), 0.7f);
    EXPECT_EQ(volumeExtinction(box, {0.0, 0.0, -6.5}), 0.0);
}

// The quadrature converges: its answer at the default tolerance is within 1e-5 of a ten times
// finer one, along rays through the middle, near the rim and through a drifted pattern.
TEST(Volume, NoiseOpticalDepthConverges) {
    const Volume v = noiseVolume();
    const glm::dvec3 centre(1e5, 2.0, -3.0);
    for (const glm::dvec3& offset : {glm::dvec3(0.0), glm::dvec3(0.3, 0.6, 0.2), glm::dvec3(-1.1, -0.2, 0.9)}) {
        const glm::dvec3 origin = centre + offset + glm::dvec3(-10.0, 1.0, 4.0);
        const glm::dvec3 dir = glm::normalize(centre + offset - origin);
        const double coarse = volumeOpticalDepth(v, origin, dir, 0.0, 30.0, 1e-6);
        const double fine = volumeOpticalDepth(v, origin, dir, 0.0, 30.0, 1e-10);
        EXPECT_GT(fine, 0.1);
        EXPECT_NEAR(coarse, fine, 1e-5 * fine);
    }
}

// The pattern moves with its velocity: what lay at x at time 0 lies at x + R·v·t at time t (R the
// node's rotation), away from the shape's faded rim.
TEST(Volume, NoiseDriftsWithItsVelocity) {
    const Volume start = noiseVolume(0.0), later = noiseVolume(0.5);
    const glm::dvec3 shift = glm::dmat3(start.world) * (glm::dvec3(0.6, 0.0, 0.2) * 0.5);
    int compared = 0;
    for (int i = -3; i <= 3; ++i) {
        const glm::dvec3 x = glm::dvec3(1e5, 2.0, -3.0) + glm::dvec3(0.2 * i, 0.05 * i, -0.1 * i);
        const NoisePoint a = noisePoint(start, x), b = noisePoint(later, x + shift);
        EXPECT_NEAR(a.p.x, b.p.x, 1e-4);
        EXPECT_NEAR(a.p.y, b.p.y, 1e-4);
        EXPECT_NEAR(a.p.z, b.p.z, 1e-4);
        ++compared;
    }
    EXPECT_EQ(compared, 7);
    double differ = 0.0;
    for (int i = -20; i <= 20; ++i) {
        const glm::dvec3 x = glm::dvec3(1e5, 2.0, -3.0) + glm::dvec3(0.07 * i, 0.02 * i, 0.05 * i);
        differ += std::abs(volumeExtinction(start, x) - volumeExtinction(later, x));
    }
    EXPECT_GT(differ, 0.5);
}

TEST(Volume, NoiseExtinctionIsAtMostSigmaAndZeroOutside) {
    const Volume v = noiseVolume();
    double most = 0.0;
    for (int i = 0; i < 2000; ++i) {
        const glm::dvec3 x = glm::dvec3(1e5, 2.0, -3.0) + glm::dvec3(std::sin(i * 1.3) * 2.5, std::cos(i * 0.7) * 1.2, std::sin(i * 0.31) * 1.8);
        const double s = volumeExtinction(v, x);
        EXPECT_GE(s, 0.0);
        EXPECT_LE(s, 3.0);
        if (!volumeContains(v, x)) {
            EXPECT_EQ(s, 0.0);
        }
        most = std::max(most, s);
    }
    EXPECT_GT(most, 0.5);
}

}  // namespace
}  // namespace nimbus::media
