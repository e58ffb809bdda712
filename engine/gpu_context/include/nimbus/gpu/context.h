#pragma once
// An OpenGL 4.5 core context: headless through EGL (surfaceless Mesa, the default everywhere but
// the editor) or a GLFW window. GL entry points come from libepoxy for both.
//
// Does not: share contexts, manage more than one window, or fall back to GL versions below 4.5.
#include <memory>
#include <string>

#include "nimbus/gpu/debug.h"

namespace nimbus::gpu {

enum class ContextKind { Headless, Window };

struct ContextDesc {
    ContextKind kind = ContextKind::Headless;
    int width = 0;    // window only; 0 means 1280
    int height = 0;   // window only; 0 means 720
    const char* title = nullptr;  // window only; nullptr means "Nimbus"
    // KHR_debug output routed to the log. Default: on in debug builds (NIMBUS_DEBUG), off otherwise.
    enum class Debug { Default, On, Off } debug = Debug::Default;
};

class Context {
public:
    virtual ~Context() = default;
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;

    virtual void makeCurrent() = 0;
    virtual void swapBuffers() = 0;               // no-op when headless
    virtual bool shouldClose() const = 0;         // window closed by the user; false when headless
    virtual void pollEvents() = 0;                // no-op when headless
    virtual void framebufferSize(int& width, int& height) const = 0;  // 0×0 when headless
    virtual void* nativeWindow() const = 0;       // GLFWwindow* or nullptr

    // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)".
    std::string renderer() const;
    std::string version() const;
    bool debugEnabled() const { return debug_; }
    // GL errors since the last call (KHR_debug errors when enabled, and glGetError always).
    GlErrorReport takeGlErrors() { return errors_.take(); }

    // Throws nimbus::SystemError with the reason when no GL 4.5 core context can be made.
    static std::unique_ptr<Context> create(const ContextDesc& desc = {});

protected:
    Context() = default;
    void finishSetup(bool debug);  // after the context is current: checks the version, installs KHR_debug

private:
    bool debug_ = false;
    GlErrorLog errors_;
};

}  // namespace nimbus::gpu
