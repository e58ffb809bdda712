#include "nimbus/gpu/debug.h"

#include <epoxy/gl.h>

#include <cstdio>
#include <string>

#include "nimbus/base/log.h"

namespace nimbus::gpu {
namespace {

void GLAPIENTRY onDebugMessage(GLenum /*source*/, GLenum type, GLuint id, GLenum severity, GLsizei length,
                               const GLchar* message, const void* user) {
    if (severity == GL_DEBUG_SEVERITY_NOTIFICATION) return;
    std::string text = "GL " + std::to_string(id) + ": " + std::string(message, static_cast<std::size_t>(length));
    if (type == GL_DEBUG_TYPE_ERROR) {
        // The user pointer is the context's GlErrorLog, alive as long as the context.
        const_cast<GlErrorLog*>(static_cast<const GlErrorLog*>(user))->record(text);
        log::error(text);
    } else {
        log::debug(text);
    }
}

}  // namespace

void GlErrorLog::installDebugOutput() {
    glEnable(GL_DEBUG_OUTPUT);
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glDebugMessageCallback(onDebugMessage, this);
    glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr, GL_TRUE);
}

void GlErrorLog::record(const std::string& message) {
    std::lock_guard lock(mutex_);
    if (pending_.count++ == 0) pending_.first = message;
}

GlErrorReport GlErrorLog::take() {
    for (GLenum code = glGetError(); code != GL_NO_ERROR; code = glGetError()) {
        char buffer[48];
        std::snprintf(buffer, sizeof buffer, "glGetError 0x%04x", code);
        record(buffer);
    }
    std::lock_guard lock(mutex_);
    GlErrorReport report = std::move(pending_);
    pending_ = {};
    return report;
}

}  // namespace nimbus::gpu
