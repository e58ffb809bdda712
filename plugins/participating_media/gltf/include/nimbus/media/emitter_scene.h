#pragma once
// The emitters of a scene, for hosts without the ECS (the reference renderer, `--time T`): every
// node whose NIMBUS_participating_media object has an "emitter" is simulated from 0 to T with the
// same fixed step the real-time path uses, so both render the same particles bit for bit.
//
// Does not: own the static clouds (media_scene.h) or keep state between calls (each call simulates
// from 0; the ECS adapter keeps its EmitterSimulation objects and steps them once per update).
#include <vector>

#include "nimbus/media/gltf_document.h"
#include "nimbus/media/emitter_simulation.h"
#include "nimbus/media/media_scene.h"

namespace nimbus::media {

inline constexpr double kEmitterTimeStep = 1.0 / 60.0;  // the App's default fixed step
inline constexpr long long kMaxEmitterSteps = 100'000'000;  // --time beyond this many steps is refused

// Parses and validates `node.emitter` (which must not be null), naming the scene file and the node
// in any error. Also refuses a density curve whose product with the medium's extinction overflows.
EmitterDesc parseNodeEmitter(const GltfDocument& scene, const MediaNode& node);

// One simulation per emitter node, in node order (the nodes without an emitter are skipped).
struct SceneEmitter {
    const MediaNode* node = nullptr;
    EmitterSimulation simulation;
};
std::vector<SceneEmitter> makeSceneEmitters(const GltfDocument& scene, const MediaScene& media);

// Simulates every emitter from 0 to `time`: steps = llround(time / dt); step k covers
// [k·dt, (k+1)·dt] with computeWorldTransforms(scene, ·) at both ends. Returns their particles
// (appendParticles, node order). Throws InputError for a negative or non-finite time, or more
// than kMaxEmitterSteps steps; std::invalid_argument for dt <= 0.
ParticleSet simulateEmittersTo(const GltfDocument& scene, const MediaScene& media, double time,
                               double dt = kEmitterTimeStep);

}  // namespace nimbus::media
