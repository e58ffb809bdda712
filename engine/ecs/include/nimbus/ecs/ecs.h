#pragma once
// Nimbus ECS: generational entity handles, sparse-set component storage, views, typed resources,
// systems in ordered phases, and an App that builds plugins (ideas from EnTT, flecs and Bevy).
//
// A plugin:
//   class SmokePlugin final : public nimbus::ecs::Plugin {
//       std::string_view name() const override { return "smoke"; }
//       void build(App& app) override {
//           app.registerComponent<Emitter>("Emitter");
//           app.insertResource<SmokeSettings>();
//           app.addSystem({.name = "smoke.emit", .phase = phases::kSimulate},
//                         [](World& w) {
//                             const double dt = w.resource<FrameInfo>().timeStep;
//                             w.view<Emitter, const Transform>().each([&](Entity e, Emitter& em, const Transform& t) { ... });
//                         });
//       }
//   };
//   App app;  app.addPlugin<SmokePlugin>();  app.update();
//
// Does not: run systems in parallel, detect component changes (no signals or observers), keep
// entity hierarchies, serialise worlds, exclude components in views, or share one World between
// threads. Component and resource type ids are per process: store names, never ids.
#include "nimbus/ecs/app.h"
#include "nimbus/ecs/component_registry.h"
#include "nimbus/ecs/entity.h"
#include "nimbus/ecs/frame_info.h"
#include "nimbus/ecs/plugin.h"
#include "nimbus/ecs/resources.h"
#include "nimbus/ecs/scheduler.h"
#include "nimbus/ecs/view.h"
#include "nimbus/ecs/world.h"
