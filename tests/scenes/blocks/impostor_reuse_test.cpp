// Blocks mode's impostor reuse (planning/block_reuse.h, impostor_reuse): a camera orbiting
// content/scenes/cumulus.gltf, every frame rendered by a session that reads its impostors again
// and by one that renders them every frame. The rule's error against no reuse, frame by frame, and
// that it is reused at all.
#include <cstdio>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "../render_fixture.h"
#include "blocks_scene_fixture.h"
#include "media/media_test_support.h"

namespace nimbus::test {
namespace {

constexpr int kWidth = 320, kHeight = 180;

struct OrbitFrame {
    assets::RgbImage image;
    bool reused = false;
};

// The frames of a camera turned about the y axis through the origin (the cloud's) by `step`
// degrees per frame, its eye moving with it, starting at the file's camera.
std::vector<OrbitFrame> orbit(const std::string& scene, const std::vector<std::string>& settings, int frames, double step) {
    sandbox::Session session({.scene = std::filesystem::path(NIMBUS_CONTENT_DIR_FOR_TESTS) / "scenes" / (scene + ".gltf"), .settings = settings});
    ecs::World& world = session.app().world();
    const ecs::Entity camera = media::nodeEntity(world, "main");
    const glm::dmat4 start = world.get<scene::Transform>(camera).world;
    std::vector<OrbitFrame> out;
    for (int k = 0; k < frames; ++k) {
        world.get<scene::Transform>(camera).world = glm::rotate(glm::dmat4(1.0), glm::radians(step * k), glm::dvec3(0.0, 1.0, 0.0)) * start;
        OrbitFrame frame;
        frame.image = session.renderRealtime(kWidth, kHeight);
        const auto& state = session.app().resource<nimbus::media::ecs::MediaRendererState>();
        frame.reused = state.renderer->stats().value("impostors_reused") > 0.5;
        out.push_back(std::move(frame));
    }
    return out;
}

class ImpostorReuse : public GlSceneTest {};

// An orbit of 0.25° a frame (15°/s at 60 frames a second) under the default 1°: a refresh about
// every fourth frame. Measured at 320×180: see the printout.
TEST_F(ImpostorReuse, AnOrbitStaysWithinOnePercentOfRenderingEveryFrame) {
    constexpr int kFrames = 13;
    for (const char* scene : {"cumulus", "cumulus_aircraft"})
    for (const char* tier : {"quality=balanced", "quality=fast"}) {
        const std::vector<OrbitFrame> reused = orbit(scene, {"mode=blocks", tier}, kFrames, 0.25);
        const std::vector<OrbitFrame> fresh = orbit(scene, {"mode=blocks", tier, "impostor_reuse=0"}, kFrames, 0.25);
        int reusedFrames = 0;
        double worst = 0.0, sum = 0.0;
        for (int k = 0; k < kFrames; ++k) {
            EXPECT_FALSE(fresh[k].reused);
            const double error = relRmse(reused[k].image, fresh[k].image);
            if (!reused[k].reused) {
                // Its light slices may be an earlier frame's: the same light views, taken about
                // another eye, differ by float rounding.
                EXPECT_LE(error, 1e-6) << tier << " frame " << k << ": a refreshed frame is the frame without reuse";
                continue;
            }
            ++reusedFrames;
            worst = std::max(worst, error);
            sum += error;
            EXPECT_GT(error, 0.0) << tier << " frame " << k << ": a reused frame reads the old impostors";
        }
        std::printf("[ measured ] %s %s orbit of %d frames at 0.25 deg: %d reused, rel-RMSE against no reuse mean %.4f%%, worst %.4f%%\n",
                    scene, tier, kFrames, reusedFrames, 100.0 * sum / std::max(reusedFrames, 1), 100.0 * worst);
        EXPECT_FALSE(reused[0].reused) << tier << ": nothing to reuse in the first frame";
        EXPECT_GE(reusedFrames, kFrames / 2) << tier;
        EXPECT_LE(worst, 0.01) << tier;
    }
}

// A still camera reads everything again, to the bit; a turned sun renders everything again.
TEST_F(ImpostorReuse, AStillCameraReadsItAllAgainAndAMovedSunNothing) {
    sandbox::Session session({.scene = std::filesystem::path(NIMBUS_CONTENT_DIR_FOR_TESTS) / "scenes" / "cumulus.gltf",
                              .settings = {"mode=blocks", "quality=fast"}});
    const auto& state = session.app().resource<nimbus::media::ecs::MediaRendererState>();
    auto reused = [&](const char* key) { return state.renderer->stats().value(key) > 0.5; };
    const assets::RgbImage first = session.renderRealtime(kWidth, kHeight);
    EXPECT_FALSE(reused("impostors_reused"));
    EXPECT_FALSE(reused("light_slices_reused"));
    const assets::RgbImage still = session.renderRealtime(kWidth, kHeight);
    EXPECT_TRUE(reused("impostors_reused"));
    EXPECT_TRUE(reused("light_slices_reused"));
    EXPECT_EQ(relRmse(still, first), 0.0);

    ecs::World& world = session.app().world();
    glm::dmat4& sun = world.get<scene::Transform>(media::nodeEntity(world, "sun")).world;
    sun = glm::rotate(glm::dmat4(1.0), glm::radians(0.1), glm::dvec3(0.0, 1.0, 0.0)) * sun;
    const assets::RgbImage turned = session.renderRealtime(kWidth, kHeight);
    EXPECT_FALSE(reused("impostors_reused"));
    EXPECT_FALSE(reused("light_slices_reused"));
    EXPECT_GT(relRmse(turned, first), 0.0);
    // The same turned sun in a session of its own: the same frame.
    sandbox::Session fresh({.scene = std::filesystem::path(NIMBUS_CONTENT_DIR_FOR_TESTS) / "scenes" / "cumulus.gltf",
                            .settings = {"mode=blocks", "quality=fast"}});
    ecs::World& freshWorld = fresh.app().world();
    freshWorld.get<scene::Transform>(media::nodeEntity(freshWorld, "sun")).world = sun;
    EXPECT_EQ(relRmse(turned, fresh.renderRealtime(kWidth, kHeight)), 0.0);
}

}  // namespace
}  // namespace nimbus::test
