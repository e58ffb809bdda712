// Headless GL through EGL on Mesa's surfaceless platform: no display server, no window, no pbuffer.
// Rendering goes to framebuffer objects only.
#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <string>

#include "context_backends.h"
#include "nimbus/base/error.h"

namespace nimbus::gpu {
namespace {

std::string eglErrorName(EGLint code) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "EGL error 0x%04x", static_cast<unsigned>(code));
    return buffer;
}

class EglContext final : public Context {
public:
    explicit EglContext(bool debug) {
        if (!epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_MESA_platform_surfaceless"))
            throw SystemError("EGL_MESA_platform_surfaceless is not available (install libegl-mesa0)");
        display_ = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (display_ == EGL_NO_DISPLAY) throw SystemError("no surfaceless EGL display: " + eglErrorName(eglGetError()));
        EGLint major = 0, minor = 0;
        if (!eglInitialize(display_, &major, &minor))
            throw SystemError("eglInitialize failed: " + eglErrorName(eglGetError()));
        if (!eglBindAPI(EGL_OPENGL_API)) throw SystemError("eglBindAPI(OpenGL) failed: " + eglErrorName(eglGetError()));
        const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                                     EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                     EGL_CONTEXT_OPENGL_DEBUG, debug ? EGL_TRUE : EGL_FALSE, EGL_NONE};
        context_ = eglCreateContext(display_, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
        if (context_ == EGL_NO_CONTEXT)
            throw SystemError("no OpenGL 4.5 core context from EGL: " + eglErrorName(eglGetError()));
        makeCurrent();
    }

    ~EglContext() override {
        eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(display_, context_);
        eglTerminate(display_);
    }

    void makeCurrent() override {
        if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
            throw SystemError("eglMakeCurrent failed: " + eglErrorName(eglGetError()));
    }
    void swapBuffers() override {}
    bool shouldClose() const override { return false; }
    void pollEvents() override {}
    void framebufferSize(int& width, int& height) const override { width = height = 0; }
    void* nativeWindow() const override { return nullptr; }

private:
    EGLDisplay display_ = EGL_NO_DISPLAY;
    EGLContext context_ = EGL_NO_CONTEXT;
};

}  // namespace

std::unique_ptr<Context> createEglContext(bool debug) { return std::make_unique<EglContext>(debug); }

}  // namespace nimbus::gpu
