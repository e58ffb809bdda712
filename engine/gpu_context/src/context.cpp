#include "nimbus/gpu/context.h"

#include <epoxy/gl.h>

#include "nimbus/base/error.h"
#include "nimbus/gpu/debug.h"
#include "context_backends.h"

namespace nimbus::gpu {

std::string Context::renderer() const {
    const auto* s = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    return s ? s : "unknown";
}

std::string Context::version() const {
    const auto* s = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    return s ? s : "unknown";
}

void Context::finishSetup(bool debug) {
    if (epoxy_gl_version() < 45)
        throw SystemError("OpenGL 4.5 core is required, the driver offers " + version());
    debug_ = debug;
    if (debug_) errors_.installDebugOutput();
    // Reversed-Z depth needs [0, 1] clip depth; every pass assumes it.
    glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
    glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
}

std::unique_ptr<Context> Context::create(const ContextDesc& desc) {
    bool debug = false;
#ifdef NIMBUS_DEBUG
    debug = true;
#endif
    if (desc.debug == ContextDesc::Debug::On) debug = true;
    if (desc.debug == ContextDesc::Debug::Off) debug = false;
    std::unique_ptr<Context> context =
        desc.kind == ContextKind::Window ? createGlfwContext(desc, debug) : createEglContext(debug);
    context->finishSetup(debug);
    return context;
}

}  // namespace nimbus::gpu
