// The same scene, seed and time give the same image bit for bit (issue acceptance), rendered by two
// separate Sessions (two Apps, two simulations, two renderers) in `particles` mode; a different time
// gives a different image, so equality is not the comparison of two blank frames.
//
// Memory over long runs ("10⁵ simulated frames keep the particle memory flat") is covered by
// tests/unit/media_emitter/emitter_memory_test.cpp (EmitterMemory.*), not repeated here.
#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "media_test_support.h"

namespace nimbus::test::media {
namespace {

constexpr int kWidth = 160, kHeight = 90;

assets::RgbImage renderOnce(const std::string& scene, double time) {
    sandbox::Session session(particlesMode(contentScene(scene), time));
    return session.renderRealtime(kWidth, kHeight);
}

bool bitIdentical(const assets::RgbImage& a, const assets::RgbImage& b) {
    return a.width == b.width && a.height == b.height && a.rgb.size() == b.rgb.size() &&
           std::memcmp(a.rgb.data(), b.rgb.data(), a.rgb.size() * sizeof(float)) == 0;
}

std::size_t differingPixels(const assets::RgbImage& a, const assets::RgbImage& b) {
    std::size_t n = 0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x)
            if (a.at(x, y) != b.at(x, y)) ++n;
    return n;
}

class Determinism : public GlSceneTest {};

// Seeded emitters with turbulence, the depth sort of the billboards, the light slices: all must repeat.
TEST_F(Determinism, SameSeedAndTimeGiveIdenticalImages) {
    for (const auto& [scene, time] : {std::pair<std::string, double>{"smoke", 8.0}, {"explosion", 0.8}}) {
        const assets::RgbImage first = renderOnce(scene, time);
        const assets::RgbImage second = renderOnce(scene, time);
        EXPECT_TRUE(bitIdentical(first, second)) << scene << ": " << differingPixels(first, second) << " pixels differ";
        // Half a second later the smoke has moved: many pixels change.
        const assets::RgbImage later = renderOnce(scene, time + 0.5);
        EXPECT_GT(differingPixels(first, later), static_cast<std::size_t>(kWidth * kHeight / 50)) << scene;
    }
}

}  // namespace
}  // namespace nimbus::test::media
