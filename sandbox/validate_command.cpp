// sandbox validate SCENE [--time T]
// Loads and checks the whole scene without a GPU, then prints what it contains and what rendering
// it needs (shadow views, light slices per light, particles). Exit 0 when the scene is valid.
#include <cstdio>

#include "commands.h"
#include "nimbus/assets/scene_queries.h"
#include "nimbus/media/ecs/media_plugin.h"
#include "nimbus/media/media_renderer.h"
#include "nimbus/media/slice_plan.h"
#include "nimbus/render/light_views.h"
#include "nimbus/scene/scene_plugin.h"
#include "session.h"

namespace nimbus::sandbox {
namespace {

struct ValidateOptions {
    std::string scene;
    double time = 0.0;
};

const char* lightTypeName(assets::LightType t) {
    switch (t) {
        case assets::LightType::Directional: return "directional";
        case assets::LightType::Point: return "point";
        case assets::LightType::Spot: return "spot";
    }
    return "?";
}

int run(const ValidateOptions& o) {
    Session session({o.scene, o.time, {}});
    const assets::Scene& scene = session.scene();
    std::size_t triangles = 0;
    for (const auto& mesh : scene.meshes)
        for (const auto& p : mesh.primitives) triangles += p.indices.size() / 3;
    std::printf("%s: valid glTF 2.0\n", o.scene.c_str());
    std::printf("  nodes %zu, meshes %zu (%zu triangles), materials %zu, textures %zu, cameras %zu, animations %zu\n",
                scene.nodes.size(), scene.meshes.size(), triangles, scene.materials.size(), scene.textures.size(),
                scene.cameras.size(), scene.animations.size());

    auto& world = session.app().world();
    media::ParticleSet particles;
    media::ecs::gatherParticles(world, particles);
    const auto pose = scene::currentWorldTransforms(world);
    assets::Aabb bounds = assets::meshBounds(scene, pose);
    const assets::Aabb mediaBounds = media::particleBounds(particles);
    bounds.extend(mediaBounds);
    const auto lights = assets::resolveLights(scene, pose);
    const auto camera = assets::resolveCamera(scene, pose, "", bounds, 16.0 / 9.0);
    std::printf("  camera %s%s\n", camera.name.c_str(), camera.synthesized ? " (made to frame the scene)" : "");
    std::printf("  media: %zu particles at t = %.3f s\n", particles.size(), session.time());
    for (const auto& light : lights) {
        const auto shadowViews = render::makeLightViews(light, bounds, camera.position());
        std::printf("  light %s: %s, %zu shadow view(s)%s", light.name.c_str(), lightTypeName(light.params.type),
                    shadowViews.size(), light.synthesized ? " (default sun)" : "");
        if (!particles.empty()) {
            std::printf(", light slices:");
            for (const auto& view : render::makeLightViews(light, mediaBounds, camera.position())) {
                const auto estimate = media::estimateSlices(particles, view, camera.position());
                std::printf(" %d (depth %.2f m, column tau %.2f)", estimate.slices, estimate.depthExtent, estimate.columnDepth);
            }
        }
        std::printf("\n");
    }
    return 0;
}

}  // namespace

CommandRunner addValidateCommand(CLI::App& app) {
    auto options = std::make_shared<ValidateOptions>();
    auto* cmd = app.add_subcommand("validate", "load and check a scene, and print what rendering it needs");
    cmd->add_option("scene", options->scene, "glTF scene (.gltf or .glb)")->required();
    cmd->add_option("--time", options->time, "simulation time in seconds")->check(CLI::Range(0.0, 1e6));
    return [options] { return run(*options); };
}

}  // namespace nimbus::sandbox
