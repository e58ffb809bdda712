#pragma once
// The App's frame clock, a resource every system can read: world.resource<FrameInfo>().
// Time advances by a fixed step per update, so a simulation is the same on every machine.
#include <cstdint>

namespace nimbus::ecs {

struct FrameInfo {
    std::uint64_t index = 0;      // updates completed before this one
    double time = 0.0;            // seconds at the start of this update: index * timeStep
    double timeStep = 1.0 / 60.0; // seconds this update simulates
};

}  // namespace nimbus::ecs
