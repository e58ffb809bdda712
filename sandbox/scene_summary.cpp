#include "scene_summary.h"

#include <cstdarg>
#include <cstdio>

#include "nimbus/assets/scene_queries.h"
#include "nimbus/media/ecs/media_plugin.h"
#include "nimbus/media/media_renderer.h"
#include "nimbus/media/slice_plan.h"
#include "nimbus/render/light_views.h"
#include "nimbus/scene/scene_plugin.h"

namespace nimbus::sandbox {
namespace {

const char* lightTypeName(assets::LightType t) {
    switch (t) {
        case assets::LightType::Directional: return "directional";
        case assets::LightType::Point: return "point";
        case assets::LightType::Spot: return "spot";
    }
    return "?";
}

// printf onto `out`.
[[gnu::format(printf, 2, 3)]] void append(std::string& out, const char* format, ...) {
    char line[512];
    va_list args;
    va_start(args, format);
    std::vsnprintf(line, sizeof line, format, args);
    va_end(args);
    out += line;
}

}  // namespace

std::string summarizeScene(Session& session, const std::string& name) {
    std::string out;
    const assets::Scene& scene = session.scene();
    std::size_t triangles = 0;
    for (const auto& mesh : scene.meshes)
        for (const auto& p : mesh.primitives) triangles += p.indices.size() / 3;
    out += name + ": valid glTF 2.0\n";
    append(out, "  nodes %zu, meshes %zu (%zu triangles), materials %zu, textures %zu, cameras %zu, animations %zu\n",
           scene.nodes.size(), scene.meshes.size(), triangles, scene.materials.size(), scene.textures.size(), scene.cameras.size(),
           scene.animations.size());

    auto& world = session.app().world();
    media::ParticleSet particles;
    media::ecs::gatherParticles(world, particles);
    const auto pose = scene::currentWorldTransforms(world);
    assets::Aabb bounds = assets::meshBounds(scene, pose);
    const assets::Aabb mediaBounds = media::particleBounds(particles);
    bounds.extend(mediaBounds);
    const auto lights = assets::resolveLights(scene, pose);
    const auto camera = assets::resolveCamera(scene, pose, "", bounds, 16.0 / 9.0);
    out += "  camera " + camera.name + (camera.synthesized ? " (made to frame the scene)" : "") + "\n";
    append(out, "  media: %zu particles at t = %.3f s\n", particles.size(), session.time());
    for (const auto& light : lights) {
        const auto shadowViews = render::makeLightViews(light, bounds, camera.position());
        out += "  light " + light.name + ": " + lightTypeName(light.params.type) + ", " + std::to_string(shadowViews.size()) +
               " shadow view(s)" + (light.synthesized ? " (default sun)" : "");
        if (!particles.empty()) {
            out += ", light slices:";
            for (const auto& view : render::makeLightViews(light, mediaBounds, camera.position())) {
                const auto estimate = media::estimateSlices(particles, view, camera.position());
                append(out, " %d (depth %.2f m, column tau %.2f)", estimate.slices, estimate.depthExtent, estimate.columnDepth);
            }
        }
        out += "\n";
    }
    return out;
}

}  // namespace nimbus::sandbox
