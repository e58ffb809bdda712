#pragma once
// The App owns a World and a Scheduler, builds plugins, and runs frames: update() runs every phase
// once (each Startup system only on its first update) with a fixed time step published as the
// FrameInfo resource.
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "nimbus/ecs/component_registry.h"
#include "nimbus/ecs/frame_info.h"
#include "nimbus/ecs/plugin.h"
#include "nimbus/ecs/scheduler.h"
#include "nimbus/ecs/world.h"

namespace nimbus::ecs {

struct AppDesc {
    double fixedTimeStep = 1.0 / 60.0;  // seconds per update; must be > 0
};

class App {
public:
    explicit App(AppDesc desc = {});
    App(const App&) = delete;
    App& operator=(const App&) = delete;
    ~App();

    World& world() { return world_; }
    const World& world() const { return world_; }
    Scheduler& scheduler() { return scheduler_; }
    const ComponentRegistry& components() const { return components_; }

    // ---- plugins: each name is built once; later additions of the same name are ignored ----
    template <class P, class... Args>
    bool addPlugin(Args&&... args) {
        return addPlugin(std::make_unique<P>(std::forward<Args>(args)...));
    }
    // Calls plugin->build(*this) unless a plugin of that name was added; returns whether it built.
    bool addPlugin(std::unique_ptr<Plugin> plugin);
    bool hasPlugin(std::string_view name) const;

    // ---- what plugins register ----
    template <class T>
    bool registerComponent(std::string name) {
        return components_.add<T>(std::move(name));
    }
    bool addPhase(std::string name, std::string_view after, PhaseRun run = PhaseRun::EveryUpdate) {
        return scheduler_.addPhase(std::move(name), after, run);
    }
    bool addSystem(SystemDesc desc, SystemFn fn) { return scheduler_.addSystem(std::move(desc), std::move(fn)); }

    template <class T, class... Args>
    T& insertResource(Args&&... args) {
        return world_.insertResource<T>(std::forward<Args>(args)...);
    }
    template <class T>
    T& resource() {
        return world_.resource<T>();
    }
    template <class T>
    T* tryResource() {
        return world_.tryResource<T>();
    }
    template <class T>
    bool hasResource() const {
        return world_.hasResource<T>();
    }

    // ---- running ----
    // One frame: sets FrameInfo, runs every phase in order, then advances the frame counter.
    void update();
    // One frame that runs the phases in order up to and including `lastPhase` (e.g. Simulate, to
    // advance a simulation without rendering); the clock advances as in update().
    void update(std::string_view lastPhase);
    // Runs one phase alone (e.g. Render to redraw a paused scene); FrameInfo and frame() stay as they are.
    void runPhase(std::string_view phase);
    // Prepare, Render and Present alone: draws the current state again (a timed frame, a new
    // camera) without simulating or advancing the clock.
    void redraw();
    std::uint64_t frame() const { return frame_; }  // updates completed
    double timeStep() const { return desc_.fixedTimeStep; }

private:
    void publishFrameInfo();

    // Destroyed in reverse order of declaration: the systems first (their closures may point into
    // the World and the plugins), then the World, and the plugins last.
    std::vector<std::unique_ptr<Plugin>> plugins_;
    AppDesc desc_;
    ComponentRegistry components_;
    World world_;
    Scheduler scheduler_;
    std::uint64_t frame_ = 0;
};

}  // namespace nimbus::ecs
