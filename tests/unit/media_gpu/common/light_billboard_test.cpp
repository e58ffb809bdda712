// The quad a particle covers in a perspective light view (shaders/media/common/light_billboard.glsl,
// read through shaders/light_billboard_probe.comp): it holds every ray from the light that meets
// the sphere ahead of the light, and a sphere that reaches behind the light covers only the part of
// the view its part ahead can reach, not the whole view (a lamp among particles: most of them
// reach behind some of its six faces).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "compute_probe.h"
#include "gpu/gl_test_context.h"

namespace nimbus::media {
namespace {

class LightBillboardGlsl : public gpu::test::GlTest {};

// A cube face's projection: 90° square, the light at the origin looking down −Z.
const glm::mat4 kFace = glm::perspective(glm::radians(90.0f), 1.0f, 0.01f, 100.0f);

std::vector<glm::vec4> rectsOf(const std::vector<glm::vec4>& spheres) {
    return test::runComputeProbe<glm::vec4>("light_billboard_probe.comp", spheres, spheres.size(), [&](GLuint program) {
        glProgramUniform1ui(program, 0, static_cast<GLuint>(spheres.size()));
        glProgramUniformMatrix4fv(program, 1, 1, GL_FALSE, &kFace[0][0]);
    });
}

// Whether the ray from the origin through NDC point `ndc` of kFace meets the sphere ahead of the light.
bool rayMeets(glm::vec2 ndc, glm::vec4 sphere) {
    const glm::dvec3 dir = glm::normalize(glm::dvec3(ndc.x, ndc.y, -1.0));  // tan 45° = 1
    const glm::dvec3 c(sphere);
    const double tc = glm::dot(c, dir), b2 = glm::dot(c, c) - tc * tc, r2 = double(sphere.w) * sphere.w;
    return b2 < r2 && tc + std::sqrt(r2 - b2) > 0.0;
}

// Spheres all around the light, many reaching behind it: every NDC sample whose ray meets one lies
// in its rectangle (one sample in 10⁻³ of the view's width of its edge may fall out by rounding).
TEST_F(LightBillboardGlsl, CoversEveryRayThatMeetsTheSphereAheadOfTheLight) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> place(-3.0f, 3.0f), size(0.05f, 2.0f);
    std::vector<glm::vec4> spheres;
    while (spheres.size() < 400) {
        const glm::vec4 s(place(rng), place(rng), place(rng), size(rng));
        if (glm::length(glm::vec3(s)) > 1.01f * s.w) spheres.push_back(s);  // the light outside it
    }
    const std::vector<glm::vec4> rects = rectsOf(spheres);
    std::size_t reachBehind = 0, smaller = 0, outside = 0;
    for (std::size_t i = 0; i < spheres.size(); ++i) {
        const glm::vec4 s = spheres[i], r = rects[i];
        const bool behind = -s.z - s.w <= 0.0f && -s.z + s.w > 0.0f;
        reachBehind += behind ? 1 : 0;
        if (behind && (r.z - r.x) * (r.w - r.y) < 3.99f) ++smaller;
        for (int y = 0; y < 64; ++y)
            for (int x = 0; x < 64; ++x) {
                const glm::vec2 ndc((x + 0.5f) / 32.0f - 1.0f, (y + 0.5f) / 32.0f - 1.0f);
                if (!rayMeets(ndc, s)) continue;
                const float slack = 1e-3f;
                if (ndc.x < r.x - slack || ndc.x > r.z + slack || ndc.y < r.y - slack || ndc.y > r.w + slack) {
                    ++outside;
                    ADD_FAILURE() << "sphere " << s.x << " " << s.y << " " << s.z << " r " << s.w << ": NDC " << ndc.x << " " << ndc.y
                                  << " outside [" << r.x << ", " << r.z << "] x [" << r.y << ", " << r.w << "]";
                    if (outside > 5) return;
                }
            }
    }
    std::printf("[light billboard] %zu of %zu spheres reach behind the light; %zu of them cover less than the whole view\n",
                reachBehind, spheres.size(), smaller);
    EXPECT_GT(reachBehind, 50u);
    EXPECT_GT(smaller, reachBehind / 2) << "a sphere reaching behind the light covers only what its part ahead can reach";
}

// A sphere beside the light, reaching behind this face's plane: its part ahead lies outside the
// face's 90° (slopes ≥ cot 30° = 1.73 for a sphere at distance 1, radius ½), so it covers nothing;
// the light inside a sphere sees it everywhere.
TEST_F(LightBillboardGlsl, ASphereBesideTheFaceCoversNothingAndOneAroundTheLightEverything) {
    const std::vector<glm::vec4> rects = rectsOf({{1.0f, 0.0f, 0.0f, 0.5f}, {0.0f, 0.0f, 0.1f, 0.5f}, {0.3f, 0.0f, 0.0f, 0.5f}});
    EXPECT_GE(rects[0].z - rects[0].x, 0.0f);
    EXPECT_FLOAT_EQ((rects[0].z - rects[0].x) * (rects[0].w - rects[0].y), 0.0f) << "no area";
    EXPECT_EQ(rects[1], glm::vec4(-1.0f, -1.0f, 1.0f, 1.0f));
    EXPECT_EQ(rects[2], glm::vec4(-1.0f, -1.0f, 1.0f, 1.0f));
}

}  // namespace
}  // namespace nimbus::media
