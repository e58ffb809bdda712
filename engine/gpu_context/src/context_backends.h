#pragma once
#include <memory>

#include "nimbus/gpu/context.h"

namespace nimbus::gpu {

// Both return a current context; Context::create finishes the common setup.
std::unique_ptr<Context> createEglContext(bool debug);
std::unique_ptr<Context> createGlfwContext(const ContextDesc& desc, bool debug);

}  // namespace nimbus::gpu
