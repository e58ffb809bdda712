// The noise volumes' density field (noise_field.h): the C++ and the GLSL (media/common/noise.glsl,
// run by shaders/noise_probe.comp here) give the same bits on a grid of points, for both kinds and
// a spread of parameters; and the field's own properties (range, coverage, falloff, determinism).
#include "nimbus/media/noise_field.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <vector>

#include "compute_probe.h"
#include "gpu/gl_test_context.h"
#include "nimbus/gpu/gl_objects.h"
#include "nimbus/gpu/shader_program.h"

namespace nimbus::media {
namespace {

class NoiseFieldGlsl : public gpu::test::GlTest {};

// Noise-space points: a lattice with fractional offsets across several cells, points far from the
// origin, and points on lattice planes; each with a unit-frame point inside and just outside.
std::vector<glm::vec3> probePoints() {
    std::vector<glm::vec3> out;
    for (int z = 0; z < 13; ++z)
        for (int y = 0; y < 13; ++y)
            for (int x = 0; x < 13; ++x) out.push_back(glm::vec3(x, y, z) * 3.1371f - glm::vec3(19.7f, 17.2f, 21.05f));
    for (float big : {1.0e3f, 3.3e4f, -1.2e5f, 7.7e6f}) out.push_back({big, -0.37f * big, 0.81f * big + 0.25f});
    for (int i = -4; i <= 4; ++i) out.push_back(glm::vec3(static_cast<float>(i), 0.0f, -static_cast<float>(i)));
    return out;
}

glm::vec3 unitFor(std::size_t i) {
    const float a = static_cast<float>(i % 97) / 97.0f * 2.3f - 1.15f;
    return {a, 0.6f * a, -0.4f * a + 0.1f};
}

struct Probe {
    std::vector<float> pattern, density;
};

Probe runGpu(const NoiseParams& n, bool ellipsoid, const std::vector<glm::vec3>& points) {
    // The probe's own folder first; its #include of media/common/noise.glsl finds the built-in copy.
    std::vector<glm::vec4> in;
    for (std::size_t i = 0; i < points.size(); ++i) {
        in.push_back(glm::vec4(points[i], 0.0f));
        in.push_back(glm::vec4(unitFor(i), 0.0f));
    }
    const std::vector<glm::vec2> values = test::runComputeProbe<glm::vec2>("noise_probe.comp", in, points.size(), [&](GLuint program) {
        glProgramUniform4ui(program, 0, n.kind, n.octaves, n.seed, ellipsoid ? 1u : 0u);
        glProgramUniform4f(program, 1, n.gain, n.invAmplitude, n.coverage, n.invOneMinusCoverage);
        glProgramUniform1f(program, 2, n.invFalloff);
        glProgramUniform1ui(program, 3, static_cast<GLuint>(points.size()));
    });
    Probe out;
    for (const glm::vec2& v : values) {
        out.pattern.push_back(v.x);
        out.density.push_back(v.y);
    }
    return out;
}

void expectSameBits(const NoiseField& field, bool ellipsoid) {
    const NoiseParams n = noiseParams(field, ellipsoid);
    const std::vector<glm::vec3> points = probePoints();
    const Probe gpu = runGpu(n, ellipsoid, points);
    ASSERT_EQ(gpu.pattern.size(), points.size());
    std::size_t differ = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
        const float pattern = noisePattern(n, points[i]);
        const float density = noiseDensity(n, points[i], unitFor(i), ellipsoid);
        const bool same = std::bit_cast<std::uint32_t>(pattern) == std::bit_cast<std::uint32_t>(gpu.pattern[i]) &&
                          std::bit_cast<std::uint32_t>(density) == std::bit_cast<std::uint32_t>(gpu.density[i]);
        if (!same && differ++ == 0)
            ADD_FAILURE() << "point " << i << " (" << points[i].x << ", " << points[i].y << ", " << points[i].z << "): C++ " << pattern << " / "
                          << density << ", GLSL " << gpu.pattern[i] << " / " << gpu.density[i];
    }
    EXPECT_EQ(differ, 0u) << "of " << points.size() << " points";
}

TEST_F(NoiseFieldGlsl, ValueNoiseIsTheSameBitsInGlsl) {
    expectSameBits({.kind = NoiseKind::Value, .octaves = 1}, false);
    expectSameBits({.kind = NoiseKind::Value, .octaves = 4, .seed = 7, .gain = 0.5, .coverage = 0.3, .falloff = 0.25}, true);
    expectSameBits({.kind = NoiseKind::Value, .octaves = 8, .seed = 0xDEADBEEFu, .gain = 0.8, .coverage = 0.55, .falloff = 0.6}, false);
    expectSameBits({.kind = NoiseKind::Value, .octaves = kMaxNoiseOctaves, .seed = 1, .gain = 1.0}, true);
}

TEST_F(NoiseFieldGlsl, SinesAreTheSameBitsInGlsl) {
    expectSameBits({.kind = NoiseKind::Sines, .octaves = 1, .gain = 0.707}, false);
    expectSameBits({.kind = NoiseKind::Sines, .octaves = 5, .seed = 42, .gain = 0.707, .coverage = 0.2, .falloff = 0.3}, true);
    expectSameBits({.kind = NoiseKind::Sines, .octaves = 9, .seed = 0xFFFFFFFFu, .gain = 0.9, .falloff = 1.0}, false);
}

TEST(NoiseFieldCpu, SinMatchesTheLibraryWithinItsPolynomial) {
    double worst = 0.0;
    for (int i = -20000; i <= 20000; ++i) {
        const float x = static_cast<float>(i) * 0.01731f;
        worst = std::max(worst, std::abs(static_cast<double>(noiseSin(x)) - std::sin(static_cast<double>(x))));
    }
    EXPECT_LT(worst, 1e-6);
}

TEST(NoiseFieldCpu, PatternStaysInItsRangeAndCoverageAndFalloffCutIt) {
    for (const NoiseKind kind : {NoiseKind::Value, NoiseKind::Sines}) {
        const NoiseParams plain = noiseParams({.kind = kind, .octaves = 5, .seed = 3, .gain = 0.6}, false);
        const NoiseParams covered = noiseParams({.kind = kind, .octaves = 5, .seed = 3, .gain = 0.6, .coverage = 0.5, .falloff = 0.5}, false);
        float lo = 1.0f, hi = 0.0f;
        for (const glm::vec3& p : probePoints()) {
            const float n = noisePattern(plain, p);
            lo = std::min(lo, n);
            hi = std::max(hi, n);
            EXPECT_EQ(noiseDensity(covered, p, glm::vec3(0.0f), false), n <= 0.5f ? 0.0f : (n - 0.5f) * 2.0f);
            EXPECT_EQ(noiseDensity(covered, p, glm::vec3(0.0f, 1.0f, 0.0f), false), 0.0f);  // at the surface: faded out
        }
        EXPECT_GE(lo, 0.0f);
        EXPECT_LE(hi, 1.0f);
        EXPECT_LT(lo, 0.35f);  // the pattern uses its range
        EXPECT_GT(hi, 0.65f);
    }
}

TEST(NoiseFieldCpu, SeedsGiveDifferentPatterns) {
    const NoiseParams a = noiseParams({.octaves = 3, .seed = 1}, false), b = noiseParams({.octaves = 3, .seed = 2}, false);
    int same = 0;
    for (const glm::vec3& p : probePoints()) same += noisePattern(a, p) == noisePattern(b, p) ? 1 : 0;
    EXPECT_LT(same, 20);
}

}  // namespace
}  // namespace nimbus::media
