// SceneRenderer (render/scene_renderer.h) on a real context: a frame runs only the passes the scene
// needs, unlit or empty scenes give exactly what the lighting model says, the output follows the
// requested size, and a frame is deterministic.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include <glm/gtc/matrix_transform.hpp>

#include "nimbus/render/gpu_scene.h"
#include "nimbus/render/scene_renderer.h"
#include "render_fixture.h"
#include "scene_geometry.h"

namespace nimbus::test {
namespace {

const glm::vec3 kBase(0.5f, 0.4f, 0.3f);
const glm::vec3 kAmbient(0.2f, 0.25f, 0.3f);
const glm::vec3 kBackground(0.05f, 0.06f, 0.07f);

assets::Scene groundScene() {
    assets::Scene s;
    assets::Material m;
    m.baseColorFactor = glm::vec4(kBase, 1.0f);
    s.materials = {m};
    s.meshes.push_back({"ground", {quad({-50, 0, -50}, {0, 0, 100}, {100, 0, 0}, 0)}});
    s.meshes.push_back({"box", {box({-1, 0, -1}, {1, 2, 1}, 0)}});
    return s;
}

render::FrameInput input(const render::GpuScene& gpu, bool withSun, bool withMeshes) {
    render::FrameInput in;
    in.gpuScene = &gpu;
    if (withMeshes) in.instances = {{0, glm::dmat4(1.0)}, {1, glm::dmat4(1.0)}};
    if (withSun) {
        assets::ResolvedLight sun;
        sun.params.intensity = 3.0f;
        sun.direction = glm::normalize(glm::dvec3(-0.3, -1.0, -0.2));
        in.lights = {sun};
    }
    in.camera.params.yfov = 0.9;
    in.camera.world = glm::inverse(glm::lookAt(glm::dvec3(6, 2, 8), glm::dvec3(0, 0.5, 0), glm::dvec3(0, 1, 0)));
    in.environment.background = kBackground;
    in.environment.ambient = kAmbient;
    return in;
}

class SceneRendererTest : public GlSceneTest {
protected:
    assets::Scene scene = groundScene();
    std::unique_ptr<render::GpuScene> gpu;
    std::unique_ptr<render::SceneRenderer> renderer;
    void SetUp() override {
        GlSceneTest::SetUp();
        gpu = std::make_unique<render::GpuScene>(scene);
        renderer = std::make_unique<render::SceneRenderer>();
    }
    assets::RgbImage render(const render::FrameInput& in, int w, int h) {
        renderer->render(in, {.width = w, .height = h, .shadowMapSize = 256, .pcfRadius = -1}, {});
        return renderer->readOutput();
    }
};

TEST_F(SceneRendererTest, LitMeshesRunShadowOpaqueAndCompose) {
    render(input(*gpu, true, true), 64, 48);
    EXPECT_EQ(renderer->lastActivePasses(), (std::vector<std::string>{"shadow_maps", "opaque", "compose"}));
    EXPECT_EQ(context().takeGlErrors().count, 0u);
}

TEST_F(SceneRendererTest, WithoutLightsThereIsNoShadowPassAndOnlyAmbient) {
    const assets::RgbImage image = render(input(*gpu, false, true), 64, 48);
    EXPECT_EQ(renderer->lastActivePasses(), (std::vector<std::string>{"opaque", "compose"}));
    // Every pixel is either background or a surface lit by ambient alone: base · L_amb.
    const glm::vec3 ambientOnly = kBase * kAmbient;
    int surface = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const glm::vec3 p = image.at(x, y);
            if (glm::length(p - kBackground) < 1e-6f) continue;
            ++surface;
            EXPECT_LT(glm::length(p - ambientOnly), 1e-6f) << "pixel (" << x << ", " << y << ")";
        }
    EXPECT_GT(surface, 64 * 48 / 2);
    EXPECT_EQ(context().takeGlErrors().count, 0u);
}

TEST_F(SceneRendererTest, AnEmptyFrameIsBackground) {
    const assets::RgbImage image = render(input(*gpu, true, false), 32, 16);
    EXPECT_EQ(renderer->lastActivePasses(), (std::vector<std::string>{"opaque", "compose"}));
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) ASSERT_EQ(image.at(x, y), kBackground) << x << ", " << y;
}

TEST_F(SceneRendererTest, OutputFollowsTheRequestedSize) {
    EXPECT_EQ(render(input(*gpu, true, true), 40, 30).width, 40);
    const assets::RgbImage resized = render(input(*gpu, true, true), 24, 50);
    EXPECT_EQ(resized.width, 24);
    EXPECT_EQ(resized.height, 50);
    EXPECT_EQ(renderer->output().desc().width, 24);
    EXPECT_EQ(renderer->output().desc().format, static_cast<GLenum>(GL_RGBA32F));
}

TEST_F(SceneRendererTest, FramesAreDeterministic) {
    const assets::RgbImage first = render(input(*gpu, true, true), 64, 48);
    const assets::RgbImage second = render(input(*gpu, true, true), 64, 48);
    EXPECT_EQ(first.rgb, second.rgb);
}

assets::ResolvedLight light(assets::LightType type, glm::dvec3 position, glm::dvec3 direction, float intensity) {
    assets::ResolvedLight l;
    l.params.type = type;
    l.params.intensity = intensity;
    l.params.outerConeAngle = 0.6;
    l.position = position;
    l.direction = glm::normalize(direction);
    return l;
}

// Directional and spot lights ahead of the first point light take the vertex-stage path of
// shaders/opaque.frag (up to four), the rest the per-fragment one: the same sum either way, so the
// order of the lights changes the image by float rounding only (and a shadow-map comparison that
// the rounding flips on a rare texel).
TEST_F(SceneRendererTest, LightOrderChangesTheImageOnlyByRounding) {
    using assets::LightType;
    const std::vector<assets::ResolvedLight> lights = {
        light(LightType::Directional, {}, {-0.3, -1.0, -0.2}, 2.0f),
        light(LightType::Spot, {3, 4, 2}, {-0.5, -1.0, -0.3}, 60.0f),
        light(LightType::Directional, {}, {0.6, -0.8, 0.1}, 1.0f),
        light(LightType::Spot, {-3, 3, 3}, {0.6, -1.0, -0.5}, 40.0f),
        light(LightType::Directional, {}, {0.1, -0.5, 0.9}, 0.5f),
        light(LightType::Point, {1.5, 1.0, 1.5}, {0, -1, 0}, 30.0f),
    };
    render::FrameInput in = input(*gpu, false, true);
    in.lights = lights;  // four vertex lights, then the sun and the point light per fragment
    const assets::RgbImage vertex = render(in, 96, 72);
    std::rotate(in.lights.rbegin(), in.lights.rbegin() + 1, in.lights.rend());  // the point light first: all per fragment
    const assets::RgbImage fragment = render(in, 96, 72);
    int differing = 0;
    double worst = 0.0;
    for (int y = 0; y < vertex.height; ++y)
        for (int x = 0; x < vertex.width; ++x) {
            const glm::vec3 a = vertex.at(x, y), b = fragment.at(x, y);
            const double difference = glm::length(a - b) / std::max(glm::length(b), 1e-6f);
            worst = std::max(worst, difference);
            if (difference > 1e-5) ++differing;
        }
    EXPECT_LE(differing, vertex.width * vertex.height / 200) << "worst relative difference " << worst;
    EXPECT_EQ(context().takeGlErrors().count, 0u);
}

// A point light's six faces drawn in half of each layer's side (pointShadowScale 0.5, the balanced
// and fast tiers') cast the box's shadow where the whole layers do: only its edge moves by a texel.
// Lookups that missed the corner the faces are drawn in would read other texels and lose it.
TEST_F(SceneRendererTest, PointLightFacesInPartOfTheirLayersCastTheSameShadow) {
    render::FrameInput in = input(*gpu, false, true);
    in.lights = {light(assets::LightType::Point, {2.0, 3.0, 1.5}, {0, -1, 0}, 40.0f)};
    auto frame = [&](float scale, bool box) {
        render::FrameInput f = in;
        if (!box) f.instances.pop_back();
        renderer->render(f, {.width = 96, .height = 72, .shadowMapSize = 512, .pointShadowScale = scale, .pcfRadius = 1}, {});
        return renderer->readOutput();
    };
    // Mean |a − b| over the ground's pixels (the box's own ones excepted), over their mean radiance.
    const assets::RgbImage noBox = frame(1.0f, false);
    auto difference = [&](const assets::RgbImage& a, const assets::RgbImage& b) {
        double sum = 0.0, mean = 0.0;
        for (int y = 0; y < a.height; ++y)
            for (int x = 0; x < a.width; ++x) {
                if (noBox.at(x, y) == kBackground) continue;
                sum += glm::length(a.at(x, y) - b.at(x, y));
                mean += glm::length(b.at(x, y));
            }
        return sum / mean;
    };
    const assets::RgbImage whole = frame(1.0f, true), half = frame(0.5f, true);
    EXPECT_GT(difference(whole, noBox), 0.02) << "the box shadows the ground";
    std::printf("[ measured ] shadow %.4f, half against whole faces %.4f\n", difference(whole, noBox), difference(half, whole));
    EXPECT_LT(difference(half, whole), 0.1 * difference(whole, noBox));
    EXPECT_EQ(context().takeGlErrors().count, 0u);
}

TEST_F(SceneRendererTest, ReadOutputPutsRowZeroAtTheTop) {
    // The ground fills the lower half of the view and the sky (background) the top rows.
    const assets::RgbImage image = render(input(*gpu, false, true), 64, 48);
    EXPECT_EQ(image.at(32, 0), kBackground);
    EXPECT_NE(image.at(32, 47), kBackground);
}

}  // namespace
}  // namespace nimbus::test
