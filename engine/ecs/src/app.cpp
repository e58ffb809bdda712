#include "nimbus/ecs/app.h"

#include "nimbus/ecs/detail/message.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace nimbus::ecs {

App::App(AppDesc desc) : desc_(desc) {
    if (!(std::isfinite(desc_.fixedTimeStep) && desc_.fixedTimeStep > 0.0))
        throw std::logic_error("App: AppDesc::fixedTimeStep must be a positive number of seconds");
    world_.insertResource<FrameInfo>(FrameInfo{0, 0.0, desc_.fixedTimeStep});
}

App::~App() = default;  // members go in reverse: systems, then the World, then the plugins

bool App::hasPlugin(std::string_view name) const {
    return std::any_of(plugins_.begin(), plugins_.end(), [&](const auto& p) { return p->name() == name; });
}

bool App::addPlugin(std::unique_ptr<Plugin> plugin) {
    if (!plugin) throw std::logic_error("App::addPlugin: null plugin");
    if (plugin->name().empty()) throw std::logic_error("App::addPlugin: a plugin needs a name");
    if (hasPlugin(plugin->name())) return false;
    // Recorded before build(), so a plugin that (indirectly) adds itself again is not rebuilt.
    plugins_.push_back(std::move(plugin));
    Plugin& added = *plugins_.back();
    try {
        added.build(*this);
    } catch (...) {
        // Not recorded as built; whatever build() registered before throwing stays registered.
        plugins_.erase(std::find_if(plugins_.begin(), plugins_.end(), [&](const auto& p) { return p.get() == &added; }));
        throw;
    }
    return true;
}

void App::publishFrameInfo() {
    FrameInfo* found = world_.tryResource<FrameInfo>();  // kept, not replaced: systems may hold a reference
    FrameInfo& info = found ? *found : world_.insertResource<FrameInfo>();
    info.index = frame_;
    info.time = static_cast<double>(frame_) * desc_.fixedTimeStep;  // not a running sum: no drift
    info.timeStep = desc_.fixedTimeStep;
}

void App::update() {
    publishFrameInfo();
    scheduler_.runAll(world_);
    ++frame_;
}

void App::update(std::string_view lastPhase) {
    if (!scheduler_.hasPhase(lastPhase)) throw std::logic_error(detail::message({"App::update: no phase named ", detail::quoted(lastPhase)}));
    publishFrameInfo();
    for (const std::string& phase : scheduler_.phaseOrder()) {
        scheduler_.runPhase(phase, world_);
        if (phase == lastPhase) break;
    }
    ++frame_;
}

void App::runPhase(std::string_view phase) { scheduler_.runPhase(phase, world_); }

void App::redraw() {
    runPhase(phases::kPrepare);
    runPhase(phases::kRender);
    runPhase(phases::kPresent);
}

}  // namespace nimbus::ecs
