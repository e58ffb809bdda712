#pragma once
// Test helpers for the participating-media scene tests: where the scenes are, a real-time frame and
// the reference image of one Session (one load, one simulation, both renderers see the same state),
// and the image measures the tests assert on.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "nimbus/assets/image_io.h"
#include "nimbus/media/reference/image_metrics.h"
#include "nimbus/media/reference/reference_renderer.h"
#include "nimbus/scene/components.h"
#include "render_fixture.h"
#include "session.h"

namespace nimbus::test::media {

// Scenes written by tests/data/media_scenes/generate_media_scenes.py.
inline std::filesystem::path mediaScene(const std::string& name) {
    return std::filesystem::path(NIMBUS_TEST_DATA_DIR) / "media_scenes" / (name + ".gltf");
}

// The authored content scenes (tools/scenegen/make_scenes.py).
inline std::filesystem::path contentScene(const std::string& name) {
    return std::filesystem::path(NIMBUS_CONTENT_DIR_FOR_TESTS) / "scenes" / (name + ".gltf");
}

// A Session in `particles` mode (named explicitly, so a change of the default cannot move these tests).
inline sandbox::SessionOptions particlesMode(const std::filesystem::path& scene, double time = 0.0,
                                             std::vector<std::string> settings = {}) {
    std::vector<std::string> all{"mode=particles"};
    all.insert(all.end(), settings.begin(), settings.end());
    return {.scene = scene, .time = time, .settings = std::move(all), .scattering = assets::Scattering::Single};  // the single reference's model
}

// The reference image of the session's current state (the same camera rule, particles and poses).
inline assets::RgbImage renderReference(sandbox::Session& session, int width, int height) {
    const auto scene = sandbox::makeReferenceScene(session, "", width, height);
    nimbus::media::reference::ReferenceSettings settings;
    settings.scattering = assets::Scattering::Single;  // today's real-time model
    settings.width = width;
    settings.height = height;
    settings.progress = false;
    return nimbus::media::reference::renderReference(scene->inputs, settings);
}

struct FramePair {
    assets::RgbImage realtime;
    assets::RgbImage reference;
};

// Both renderers on one session of `scene` at `time` (needs a current GL context: GlSceneTest).
inline FramePair renderBoth(const std::filesystem::path& scene, double time, int width, int height) {
    sandbox::Session session(particlesMode(scene, time));
    FramePair out;
    out.realtime = session.renderRealtime(width, height);
    out.reference = renderReference(session, width, height);
    return out;
}

inline double luminance(const glm::vec3& c) { return nimbus::media::reference::luminance(c.r, c.g, c.b); }

// Channels of `image` that are NaN or infinite.
inline std::size_t countNonfinite(const assets::RgbImage& image) {
    return static_cast<std::size_t>(std::count_if(image.rgb.begin(), image.rgb.end(), [](float v) { return !std::isfinite(v); }));
}

// The entity spawned from the node called `name` (fails the test when there is none).
inline ecs::Entity nodeEntity(ecs::World& world, const std::string& name) {
    ecs::Entity found = ecs::kNullEntity;
    world.view<scene::SceneNode>().each([&](ecs::Entity e, const scene::SceneNode& node) {
        if (node.name == name) found = e;
    });
    EXPECT_NE(found, ecs::kNullEntity) << "no node named " << name;
    return found;
}

// Largest |L(x+1) - L(x)| of luminance along row y between columns x0 and x1 (inclusive), and where.
struct Jump {
    double size = 0.0;
    int x = -1;  // the left pixel of the pair
};
inline Jump largestJump(const std::vector<double>& line) {
    Jump out;
    for (std::size_t i = 0; i + 1 < line.size(); ++i) {
        const double d = std::abs(line[i + 1] - line[i]);
        if (d > out.size) out = {d, static_cast<int>(i)};
    }
    return out;
}

inline std::vector<double> luminanceRow(const assets::RgbImage& image, int y) {
    std::vector<double> out(static_cast<std::size_t>(image.width));
    for (int x = 0; x < image.width; ++x) out[static_cast<std::size_t>(x)] = luminance(image.at(x, y));
    return out;
}

}  // namespace nimbus::test::media
