#include "nimbus/media/emitter_scene.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "nimbus/base/error.h"

namespace nimbus::media {

EmitterDesc parseNodeEmitter(const GltfDocument& scene, const MediaNode& node) {
    const ParseContext where{scene.displayName(), node.node, node.name, std::string("extensions.") + kMediaExtension + ".emitter"};
    EmitterDesc desc = parseEmitter(node.emitter, where);
    const float peak = *std::max_element(desc.density.values.begin(), desc.density.values.end());
    if (!(static_cast<double>(peak) * node.medium.extinction <= std::numeric_limits<float>::max()))
        where.fail("density", "times medium.extinction overflows a float");
    return desc;
}

std::vector<SceneEmitter> makeSceneEmitters(const GltfDocument& scene, const MediaScene& media) {
    std::vector<SceneEmitter> emitters;
    for (const MediaNode& node : media.nodes)
        if (!node.emitter.is_null()) emitters.push_back({&node, EmitterSimulation(parseNodeEmitter(scene, node), node.node)});
    return emitters;
}

ParticleSet simulateEmittersTo(const GltfDocument& scene, const MediaScene& media, double time, double dt) {
    if (!(dt > 0.0) || !std::isfinite(dt)) throw std::invalid_argument("simulateEmittersTo: dt must be > 0 and finite");
    if (!std::isfinite(time) || time < 0.0)
        throwInputError(scene.displayName(), "", "time", "must be a finite number of seconds >= 0, not " + std::to_string(time));
    const double steps = std::round(time / dt);
    if (steps > static_cast<double>(kMaxEmitterSteps))
        throwInputError(scene.displayName(), "", "time",
                        std::to_string(time) + " s needs more than " + std::to_string(kMaxEmitterSteps) + " simulation steps");

    std::vector<SceneEmitter> emitters = makeSceneEmitters(scene, media);
    ParticleSet out;
    if (emitters.empty()) return out;

    const long long count = std::llround(time / dt);
    std::vector<glm::dmat4> world0 = scene.worldTransforms(0.0);
    for (long long k = 0; k < count; ++k) {
        const double t0 = static_cast<double>(k) * dt;
        std::vector<glm::dmat4> world1 = scene.worldTransforms(static_cast<double>(k + 1) * dt);
        for (SceneEmitter& e : emitters) {
            const auto n = static_cast<std::size_t>(e.node->node);
            e.simulation.step(t0, dt, world0[n], world1[n]);
        }
        world0 = std::move(world1);
    }

    std::size_t total = 0;
    for (const SceneEmitter& e : emitters) total += e.simulation.size();
    out.reserve(total);
    for (const SceneEmitter& e : emitters) e.simulation.appendParticles(out, e.node->medium);
    return out;
}

}  // namespace nimbus::media
