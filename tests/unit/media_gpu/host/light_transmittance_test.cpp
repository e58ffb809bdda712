// Tests shaders/media/host/light_transmittance.glsl mediaSliceOpticalDepthAt, run by
// shaders/slice_lookup_probe.comp on slices laid out as light_slice_intervals_pass.h writes them:
// between planes τ follows a monotone cubic that is exact at every plane, never falls, and follows
// particles' τ far closer than a straight line where the planes lie a third of a radius apart.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <vector>

#include <glm/glm.hpp>

#include "common/kernel_table.h"
#include "compute_probe.h"
#include "gpu/gl_test_context.h"
#include "nimbus/gpu/gl_objects.h"
#include "nimbus/gpu/shader_program.h"
#include "nimbus/media/gpu_bindings.h"

namespace nimbus::media {
namespace {

// Two particles' optical depth up to view depth z, along one ray (radius 1: depths in radii).
double opticalDepth(double z) { return kernelSegment(0.2, z - 5.0) + 0.6 * kernelSegment(0.5, z - 6.2); }

constexpr double kNear = 3.5, kFar = 7.5;
// A third of a radius apart, as a crop's or the exact tier's planes lie across a cloud's particles.
// At two thirds (fast's whole view) the kernel, e^(−4.5 s²), is too narrow for any curve through
// the planes to follow: there a cubic errs 0.67 times as much as a line.
constexpr int kPlanes = 12;

class SliceLookupGlsl : public gpu::test::GlTest {};

TEST_F(SliceLookupGlsl, ACubicExactAtThePlanesThatNeverFallsAndFollowsTheParticles) {
    const double spacing = (kFar - kNear) / kPlanes;
    const auto plane = [&](int k) { return k <= 0 ? 0.0 : opticalDepth(kNear + std::min(k, kPlanes) * spacing); };
    std::vector<float> intervals;
    for (int k = 0; k < kPlanes; ++k)
        for (int p = k - 1; p <= k + 2; ++p) intervals.push_back(static_cast<float>(plane(p)));
    const int layers = kPlanes;
    const gpu::Texture slices({.target = GL_TEXTURE_2D_ARRAY, .format = GL_RGBA32F, .width = 1, .height = 1, .depth = layers});
    glTextureSubImage3D(slices.id(), 0, 0, 0, 0, 1, 1, layers, GL_RGBA, GL_FLOAT, intervals.data());
    glBindTextureUnit(kSlicesUnit, slices.id());

    std::vector<float> depths;
    for (int i = 0; i <= 2000; ++i) depths.push_back(static_cast<float>(3.0 + 5.0 * i / 2000.0));
    const std::vector<float> values = test::runComputeProbe<float>("slice_lookup_probe.comp", depths, depths.size(), [&](GLuint program) {
        glProgramUniform1ui(program, 0, static_cast<GLuint>(depths.size()));
        glProgramUniform4f(program, 1, 0.0f, static_cast<float>(kNear), static_cast<float>(kFar), static_cast<float>(kPlanes));
    });

    const double total = plane(kPlanes);
    double cubic = 0.0, line = 0.0;
    for (std::size_t i = 0; i < depths.size(); ++i) {
        const double z = depths[i], s = (z - kNear) / spacing;
        const double got = values[i];
        if (s <= 0.0) {
            EXPECT_EQ(got, 0.0) << "before the near plane, at " << z;
        }
        if (s >= kPlanes) {
            EXPECT_NEAR(got, total, 1e-6 * total) << "past the far plane, at " << z;
        }
        if (i > 0) {
            EXPECT_GE(got, values[i - 1] - 1e-6 * total) << "τ falls at " << z;
        }
        if (s <= 0.0 || s >= kPlanes) continue;
        const int k = static_cast<int>(std::floor(s));
        const double straight = plane(k) + (s - k) * (plane(k + 1) - plane(k));
        cubic = std::max(cubic, std::abs(got - opticalDepth(z)));
        line = std::max(line, std::abs(straight - opticalDepth(z)));
    }
    for (int k = 1; k <= kPlanes; ++k) {  // exact at the planes: depths on them, probed alone
        const double z = kNear + k * spacing;
        const auto nearest = std::min_element(depths.begin(), depths.end(), [&](float a, float b) { return std::abs(a - z) < std::abs(b - z); });
        if (std::abs(*nearest - z) < 1e-6) {
            EXPECT_NEAR(values[static_cast<std::size_t>(nearest - depths.begin())], plane(k), 1e-6 * total);
        }
    }
    std::printf("[slice lookup] worst error over the ray: cubic %.4f, a straight line %.4f, of a column of %.4f\n", cubic, line, total);
    EXPECT_LT(cubic, 0.4 * line);  // measured 0.31
}

// A lamp's view of 4 texels in an array of 8 lies in its layer's first texels (media
// slices/slice_view.h sliceTexels): read across its whole image, bilinear as over a 4-texel image
// with clamped edges, and never reading the texels past the one cleared beyond it (NaN here).
TEST_F(SliceLookupGlsl, ALampViewOfFewerTexelsIsReadInItsLayersFirstTexels) {
    constexpr int kArray = 8, kOwn = 4;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    std::vector<glm::vec4> texels(kArray * kArray, glm::vec4(nan));
    const auto value = [](int x, int y) { return static_cast<float>(1 + x + 10 * y); };
    for (int y = 0; y <= kOwn; ++y)
        for (int x = 0; x <= kOwn; ++x) texels[static_cast<std::size_t>(y * kArray + x)] = glm::vec4(x < kOwn && y < kOwn ? value(x, y) : 0.0f);
    const gpu::Texture slices({.target = GL_TEXTURE_2D_ARRAY, .format = GL_RGBA32F, .width = kArray, .height = kArray, .depth = 1});
    glTextureSubImage3D(slices.id(), 0, 0, 0, 0, kArray, kArray, 1, GL_RGBA, GL_FLOAT, texels.data());
    glBindTextureUnit(kSlicesUnit, slices.id());
    const float share = static_cast<float>(kOwn) / kArray;
    const glm::ivec4 header(1, std::bit_cast<int>(share), kOwn, std::bit_cast<int>(share - 0.5f / kArray));
    const gpu::Buffer block = gpu::createBuffer(sizeof(GpuSliceViews), nullptr, GL_DYNAMIC_STORAGE_BIT);
    glNamedBufferSubData(block.id(), 0, sizeof(header), &header);
    glBindBufferBase(GL_UNIFORM_BUFFER, kSliceViewsBinding, block.id());

    std::vector<glm::vec2> uvs;
    for (int y = 0; y <= 40; ++y)
        for (int x = 0; x <= 40; ++x) uvs.emplace_back(x / 40.0f, y / 40.0f);
    const std::vector<float> values = test::runComputeProbe<float>("slice_layer_uv_probe.comp", uvs, uvs.size(), [&](GLuint program) {
        glProgramUniform1ui(program, 0, static_cast<GLuint>(uvs.size()));
    });
    for (std::size_t i = 0; i < uvs.size(); ++i) {
        // Bilinear over the 4 texels, their centres at (t + 0.5) / 4, clamped at the edges.
        const glm::vec2 at = glm::clamp(uvs[i] * static_cast<float>(kOwn) - 0.5f, glm::vec2(0.0f), glm::vec2(kOwn - 1));
        const glm::ivec2 base = glm::min(glm::ivec2(at), glm::ivec2(kOwn - 2));
        const glm::vec2 f = at - glm::vec2(base);
        const float expected = glm::mix(glm::mix(value(base.x, base.y), value(base.x + 1, base.y), f.x),
                                        glm::mix(value(base.x, base.y + 1), value(base.x + 1, base.y + 1), f.x), f.y);
        ASSERT_TRUE(std::isfinite(values[i])) << "uv " << uvs[i].x << " " << uvs[i].y;
        EXPECT_NEAR(values[i], expected, 1e-3f) << "uv " << uvs[i].x << " " << uvs[i].y;
    }
}

}  // namespace
}  // namespace nimbus::media
