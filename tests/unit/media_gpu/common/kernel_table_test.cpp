// kernel_table.cpp: the closed form of a particle's optical depth up to a point of a ray against an
// independent quadrature, its limits, and the table the fast splats read bilinearly; and the GLSL
// closed forms of a whole chord's column (kernel_table.glsl kernelColumn, run by
// shaders/kernel_column_probe.comp) and of a span between two points (optics.glsl kernelSpan, run
// by shaders/kernel_span_probe.comp) against the C++.
#include "common/kernel_table.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/glm.hpp>

#include "compute_probe.h"
#include "gpu/gl_test_context.h"
#include "media_core/numeric_quadrature.h"
#include "nimbus/gpu/gl_objects.h"
#include "nimbus/gpu/shader_program.h"

namespace nimbus::media {
namespace {

// e^(−4.5(β² + s²)) along the ray, integrated from the sphere's entry to μ.
double quadrature(double beta, double mu) {
    if (beta >= 1.0) return 0.0;
    const double h = std::sqrt(1.0 - beta * beta);
    const double end = std::clamp(mu, -h, h);
    if (end <= -h) return 0.0;
    return static_cast<double>(test::integrate(
        [&](long double s) { return std::exp(-4.5L * (static_cast<long double>(beta * beta) + s * s)); }, -h, end));
}

TEST(KernelTable, ClosedFormMatchesQuadrature) {
    for (double beta : {0.0, 1e-6, 0.1, 0.37, 0.5, 0.8, 0.99, 0.999999})
        for (double mu : {-1.5, -1.0, -0.6, -0.1, 0.0, 1e-7, 0.3, 0.75, 1.0, 2.0})
            EXPECT_NEAR(kernelSegment(beta, mu), quadrature(beta, mu), 1e-12) << "beta " << beta << " mu " << mu;
}

TEST(KernelTable, LimitsAreExact) {
    // Nothing before the entry point, the whole chord past the exit, nothing outside the sphere.
    EXPECT_EQ(kernelSegment(0.3, -std::sqrt(1.0 - 0.09)), 0.0);
    EXPECT_EQ(kernelSegment(0.3, 5.0), kernelSegment(0.3, std::sqrt(1.0 - 0.09)));
    EXPECT_EQ(kernelSegment(1.0, 0.0), 0.0);
    EXPECT_EQ(kernelSegment(2.0, 0.0), 0.0);
    EXPECT_EQ(kernelSegment(std::nan(""), 0.0), 0.0) << "a NaN impact parameter draws nothing";
    // Half of the centre's column lies before the closest point: √π/(2√4.5)·erf(√4.5).
    EXPECT_NEAR(kernelSegment(0.0, 0.0), 0.5 * std::sqrt(M_PI / 4.5) * std::erf(std::sqrt(4.5)), 1e-15);
}

TEST(KernelTable, TexelsHoldTheClosedFormAtTheDomainsCorners) {
    const int betas = 8, mus = 16;
    const auto values = kernelTableValues(betas, mus);
    ASSERT_EQ(values.size(), static_cast<std::size_t>(betas * mus));
    for (int j = 0; j < mus; ++j)
        for (int i = 0; i < betas; ++i)
            EXPECT_FLOAT_EQ(values[static_cast<std::size_t>(j * betas + i)],
                            static_cast<float>(kernelSegment(i / double(betas - 1), 2.0 * j / (mus - 1) - 1.0)));
    EXPECT_EQ(values[betas - 1], 0.0f) << "β = 1 is the silhouette";
}

// What the splats lose to bilinear filtering between samples, relative to the centre's column:
// below 0.2% (measured 0.13%, at the kink where μ reaches the chord's end), a tenth of the fast
// tier's error against the reference.
TEST(KernelTable, BilinearFetchIsWithinTwoTenthsOfAPercent) {
    const int nb = kKernelTableBetas, nm = kKernelTableMus;
    const auto t = kernelTableValues(nb, nm);
    const double peak = kernelSegment(0.0, 1.0);
    double worst = 0.0;
    for (int j = 0; j + 1 < nm; ++j)
        for (int i = 0; i + 1 < nb; ++i) {
            auto at = [&](int a, int b) { return static_cast<double>(t[static_cast<std::size_t>(b * nb + a)]); };
            const double bilinear = 0.25 * (at(i, j) + at(i + 1, j) + at(i, j + 1) + at(i + 1, j + 1));
            const double exact = kernelSegment((i + 0.5) / (nb - 1), 2.0 * (j + 0.5) / (nm - 1) - 1.0);
            worst = std::max(worst, std::abs(bilinear - exact) / peak);
        }
    EXPECT_LT(worst, 2e-3);
    std::printf("[kernel table] %dx%d: worst bilinear error at cell centres %.2e of the peak column\n", nb, nm, worst);
}

class KernelColumnGlsl : public gpu::test::GlTest {};

// A kernel probe: one value per input item, the item count its only uniform (location 0).
template <typename Out, typename In>
std::vector<Out> runItemProbe(const char* shader, const std::vector<In>& items) {
    return test::runComputeProbe<Out>(shader, items, items.size(),
                                      [&](GLuint program) { glProgramUniform1ui(program, 0, static_cast<GLuint>(items.size())); });
}

TEST_F(KernelColumnGlsl, MatchesTheWholeChordsSegmentWithinAMillionthOfThePeak) {
    std::vector<float> betas;
    for (int i = 0; i <= 1000; ++i) betas.push_back(static_cast<float>(i) / 1000.0f);
    betas.push_back(1.5f);  // past the sphere: no column
    const std::vector<float> values = runItemProbe<float>("kernel_column_probe.comp", betas);
    const double peak = kernelSegment(0.0, 1.0);
    double worst = 0.0;
    for (std::size_t i = 0; i < betas.size(); ++i)
        worst = std::max(worst, std::abs(static_cast<double>(values[i]) - kernelSegment(betas[i], 1.0)) / peak);
    EXPECT_LT(worst, 1e-6);
    EXPECT_EQ(values.back(), 0.0f);
    std::printf("[kernel column] worst GLSL error %.2e of the peak column\n", worst);
}

// The slice deposit's span between two planes: within a millionth of the peak column everywhere,
// including spans a thousandth of a radius long, whose ends' erf values nearly cancel; never
// negative; nothing outside the sphere or for an empty span.
TEST_F(KernelColumnGlsl, SpanMatchesTheDifferenceOfSegmentsWithinAMillionthOfThePeak) {
    std::vector<glm::vec4> spans;
    for (float beta : {0.0f, 0.2f, 0.5f, 0.8f, 0.95f, 0.999f, 1.0f, 1.5f})
        for (float lo : {-2.0f, -1.0f, -0.7f, -0.3f, -0.001f, 0.0f, 0.25f, 0.6f, 0.9f, 1.2f})
            for (float length : {0.0f, 0.001f, 0.05f, 0.3f, 1.0f, 3.0f}) spans.emplace_back(beta, lo, lo + length, 0.0f);
    const std::vector<float> values = runItemProbe<float>("kernel_span_probe.comp", spans);
    const double peak = kernelSegment(0.0, 1.0);
    double worst = 0.0;
    for (std::size_t i = 0; i < spans.size(); ++i) {
        const glm::dvec3 s(spans[i]);
        const double expected = kernelSegment(s.x, s.z) - kernelSegment(s.x, s.y);
        worst = std::max(worst, std::abs(static_cast<double>(values[i]) - expected) / peak);
        EXPECT_GE(values[i], 0.0f) << "beta " << s.x << " lo " << s.y << " hi " << s.z;
        if (s.x >= 1.0 || s.z == s.y) {
            EXPECT_EQ(values[i], 0.0f) << "beta " << s.x << " lo " << s.y << " hi " << s.z;
        }
    }
    EXPECT_LT(worst, 1e-6);
    std::printf("[kernel span] worst GLSL error %.2e of the peak column\n", worst);
}

}  // namespace
}  // namespace nimbus::media
