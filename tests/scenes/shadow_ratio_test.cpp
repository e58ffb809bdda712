// A ground pixel in a box's shadow is darker than its lit neighbour by exactly the ratio the
// lighting model gives (docs/scene-format.md §4.1: L = f(l, v)·E·cosθ·V + base·L_amb, f the glTF
// BRDF of a dielectric of roughness 1, evaluated per pixel for its view direction v):
//   L_shadow / L_lit = base·L_amb / (f·E·cosθ + base·L_amb).
// The scene is built in memory and rendered the way `sandbox render` renders a file.
// Which pixels are shadowed is decided from geometry alone: the ray through the pixel centre
// meets the ground, and the sun ray from there does or does not hit the box.
#include <gtest/gtest.h>

#include <algorithm>
#include <climits>
#include <cstdlib>

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtx/quaternion.hpp>

#include "nimbus/assets/surface_brdf.h"
#include "render_fixture.h"
#include "scene_geometry.h"

namespace nimbus::test {
namespace {

constexpr int kWidth = 240, kHeight = 180;
constexpr double kGroundHalf = 10.0;
const glm::vec3 kBoxLo(-0.5f, 0.0f, -0.5f), kBoxHi(0.5f, 1.0f, 0.5f);
const glm::dvec3 kSunTravel = glm::normalize(glm::dvec3(1.0, -0.8, 0.3));
constexpr float kSunLux = 2.0f;
const glm::vec3 kAmbient(0.1f, 0.12f, 0.08f);
const glm::vec3 kGroundBase(0.6f, 0.5f, 0.4f);
// A ground point counts as surely shadowed (or surely lit) when the points this far around it are
// too: PCF filters over a few shadow-map texels (~1 cm here), well inside this margin.
constexpr double kMargin = 0.08;

const glm::dvec3 kEye(-0.6, 2.6, 3.4), kTarget(1.1, 0.0, 0.2);

// Ground, box, sun and camera as glTF nodes, ambient in the environment: the sandbox's path.
std::shared_ptr<const assets::Scene> groundBoxAndSun() {
    auto s = std::make_shared<assets::Scene>();
    assets::Material ground, red;
    ground.baseColorFactor = glm::vec4(kGroundBase, 1.0f);
    red.baseColorFactor = glm::vec4(0.8f, 0.1f, 0.1f, 1.0f);
    ground.metallicFactor = red.metallicFactor = 0.0f;  // chalk, not glTF's default metal
    s->materials = {ground, red};
    const float g = static_cast<float>(kGroundHalf);
    s->meshes.push_back({"ground", {quad({-g, 0, -g}, {0, 0, 2 * g}, {2 * g, 0, 0}, 0)}});
    s->meshes.push_back({"box", {box(kBoxLo, kBoxHi, 1)}});
    assets::Light sun;
    sun.name = "sun";
    sun.type = assets::LightType::Directional;
    sun.intensity = kSunLux;
    s->lights = {sun};
    assets::Camera camera;
    camera.name = "view";
    camera.yfov = 0.8;
    camera.znear = 0.05;
    s->cameras = {camera};

    assets::Node groundNode, boxNode, sunNode, cameraNode;
    groundNode.name = "ground";
    groundNode.mesh = 0;
    boxNode.name = "box";
    boxNode.mesh = 1;
    sunNode.name = "sun";
    sunNode.light = 0;
    // Lights shine along their node's -Z.
    sunNode.rotation = glm::rotation(glm::dvec3(0.0, 0.0, -1.0), kSunTravel);
    cameraNode.name = "view";
    cameraNode.camera = 0;
    cameraNode.translation = kEye;
    cameraNode.rotation = glm::quat_cast(glm::dmat3(glm::inverse(glm::lookAt(kEye, kTarget, glm::dvec3(0, 1, 0)))));
    s->nodes = {groundNode, boxNode, sunNode, cameraNode};
    s->rootNodes = {0, 1, 2, 3};
    s->environment.background = {0.02f, 0.03f, 0.05f};
    s->environment.ambient = kAmbient;
    return s;
}

enum class Light { Shadowed, Lit, Unsure };

// What the ground point seen through pixel (x, y) receives, from geometry; nullopt: not ground.
std::optional<Light> classify(const render::View& view, const assets::Aabb& boxBounds, int x, int y) {
    const glm::dvec3 dir = pixelRay(view, x, y);
    const auto tGround = hitGround(view.origin, dir, 0.0);
    if (!tGround) return std::nullopt;
    const auto tBox = hitBox(view.origin, dir, boxBounds);
    if (tBox && *tBox <= *tGround) return std::nullopt;  // the box is in front
    const glm::dvec3 p = view.origin + dir * *tGround;
    if (std::abs(p.x) > kGroundHalf - 0.5 || std::abs(p.z) > kGroundHalf - 0.5) return std::nullopt;
    int shadowed = 0, samples = 0;
    for (const double dx : {-kMargin, 0.0, kMargin})
        for (const double dz : {-kMargin, 0.0, kMargin}) {
            ++samples;
            if (hitBox(p + glm::dvec3(dx, 0.0, dz), -kSunTravel, boxBounds)) ++shadowed;
        }
    // Ground right at the box's foot is neither: the box's walls stand there.
    assets::Aabb grown = boxBounds;
    grown.extend(boxBounds.min - glm::dvec3(kMargin));
    grown.extend(boxBounds.max + glm::dvec3(kMargin));
    if (p.x >= grown.min.x && p.x <= grown.max.x && p.z >= grown.min.z && p.z <= grown.max.z) return Light::Unsure;
    return shadowed == samples ? Light::Shadowed : shadowed == 0 ? Light::Lit : Light::Unsure;
}

::testing::AssertionResult withinRelative(const glm::vec3& actual, const glm::vec3& expected, double tolerance) {
    for (int c = 0; c < 3; ++c)
        if (std::abs(actual[c] - expected[c]) > tolerance * std::abs(expected[c]))
            return ::testing::AssertionFailure() << "channel " << c << ": " << actual[c] << " vs " << expected[c] << " (relative error "
                                                 << std::abs(actual[c] - expected[c]) / expected[c] << ")";
    return ::testing::AssertionSuccess();
}

class ShadowRatio : public GlSceneTest {
protected:
    void SetUp() override {
        GlSceneTest::SetUp();
        const AppFrame frame = renderThroughApp(groundBoxAndSun(), kWidth, kHeight);
        EXPECT_EQ(frame.camera.name, "view");
        image = frame.image;
        view = frame.view;
        // NIMBUS_DUMP_IMAGE=frame.png keeps the frame for a look when changing the scene.
        if (const char* dump = std::getenv("NIMBUS_DUMP_IMAGE")) assets::writeImage(dump, image);
        boxBounds.extend(glm::dvec3(kBoxLo));
        boxBounds.extend(glm::dvec3(kBoxHi));
    }

    assets::RgbImage image;
    render::View view;
    assets::Aabb boxBounds;

    // The lighting model, in double, for the ground point seen through pixel (x, y).
    const double cosTheta = glm::dot(glm::dvec3(0, 1, 0), -kSunTravel);
    glm::vec3 shadowedRadiance() const { return kGroundBase * kAmbient; }
    glm::vec3 litRadiance(int x, int y) const {
        const glm::dvec3 up(0.0, 1.0, 0.0);
        const glm::dvec3 f = assets::brdfTimesCosine(assets::surfaceBrdf(glm::dvec3(kGroundBase), 0.0, 1.0), up, -pixelRay(view, x, y),
                                                     -kSunTravel, cosTheta);
        return glm::vec3(f * double(kSunLux) + glm::dvec3(kGroundBase * kAmbient));
    }
};

TEST_F(ShadowRatio, ShadowedPixelIsDarkerThanItsLitNeighbourByTheModelsRatio) {
    EXPECT_EQ(context().takeGlErrors().count, 0u);
    // The surely-shadowed and surely-lit pixels closest to each other: neighbours across the shadow's edge.
    std::vector<glm::ivec2> shadowed, lit;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const auto c = classify(view, boxBounds, x, y);
            if (c == Light::Shadowed) shadowed.push_back({x, y});
            if (c == Light::Lit) lit.push_back({x, y});
        }
    ASSERT_GT(shadowed.size(), 100u) << "the camera must see the shadow";
    ASSERT_GT(lit.size(), 1000u);
    glm::ivec2 s = shadowed[0], l = lit[0];
    int best = INT_MAX;
    for (const glm::ivec2& a : shadowed)
        for (const glm::ivec2& b : lit) {
            const glm::ivec2 d = a - b;
            if (d.x * d.x + d.y * d.y < best) best = d.x * d.x + d.y * d.y, s = a, l = b;
        }
    SCOPED_TRACE(::testing::Message() << "shadowed pixel (" << s.x << ", " << s.y << "), lit pixel (" << l.x << ", " << l.y << ")");
    EXPECT_LE(best, 8 * 8) << "neighbours";

    const glm::vec3 lShadow = image.at(s.x, s.y), lLit = image.at(l.x, l.y);
    const glm::vec3 expectedRatio = shadowedRadiance() / litRadiance(l.x, l.y);
    EXPECT_TRUE(withinRelative(lShadow / lLit, expectedRatio, 0.01)) << "L_shadow / L_lit";
    EXPECT_TRUE(withinRelative(lShadow, shadowedRadiance(), 0.01)) << "L_shadow";
    EXPECT_TRUE(withinRelative(lLit, litRadiance(l.x, l.y), 0.01)) << "L_lit";
}

TEST_F(ShadowRatio, EveryGroundPixelIsShadowedExactlyWhereGeometrySays) {
    int shadowedCount = 0, litCount = 0, wrongShadowed = 0, wrongLit = 0;
    std::string first;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const auto c = classify(view, boxBounds, x, y);
            if (c != Light::Shadowed && c != Light::Lit) continue;
            const bool inShadow = c == Light::Shadowed;
            (inShadow ? shadowedCount : litCount)++;
            const glm::vec3 expected = inShadow ? shadowedRadiance() : litRadiance(x, y);
            const auto ok = withinRelative(image.at(x, y), expected, 0.01);
            if (!ok) {
                (inShadow ? wrongShadowed : wrongLit)++;
                if (first.empty())
                    first = std::string(inShadow ? "shadowed" : "lit") + " pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                            "): " + ok.message();
            }
        }
    EXPECT_GT(shadowedCount, 100);
    EXPECT_GT(litCount, 1000);
    EXPECT_EQ(wrongShadowed, 0) << first;
    EXPECT_EQ(wrongLit, 0) << "shadow acne or a misplaced shadow: " << first;
}

}  // namespace
}  // namespace nimbus::test
