#include "egl_context.h"

#include <epoxy/gl.h>

#include <cstdio>

namespace mini {
namespace {

[[noreturn]] void fail(const std::string& what) {
    char code[16];
    std::snprintf(code, sizeof code, "0x%04x", static_cast<unsigned>(eglGetError()));
    throw GlContextError(what + " (EGL error " + code + ")");
}

EGLDisplay openDisplay() {
    // Client extensions are queried on EGL_NO_DISPLAY; surfaceless needs no X, Wayland or DRM device.
    if (epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_MESA_platform_surfaceless")) {
        EGLDisplay d = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (d != EGL_NO_DISPLAY) return d;
    }
    EGLDisplay d = eglGetDisplay(EGL_DEFAULT_DISPLAY);
    if (d == EGL_NO_DISPLAY) fail("no EGL display (surfaceless or default)");
    return d;
}

// A config for a desktop-GL context; with a pbuffer bit in case we need the 1×1 fallback surface.
EGLConfig chooseConfig(EGLDisplay display) {
    const EGLint attributes[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint count = 0;
    if (eglChooseConfig(display, attributes, &config, 1, &count) && count > 0) return config;
    const EGLint anySurface[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};  // surfaceless displays may have no pbuffers
    if (eglChooseConfig(display, anySurface, &config, 1, &count) && count > 0) return config;
    return nullptr;
}

}  // namespace

EglContext::EglContext() {
    try {
        create();
    } catch (...) {
        release();  // the destructor does not run for a half-built object
        throw;
    }
}

void EglContext::create() {
    display_ = openDisplay();
    EGLint major = 0, minor = 0;
    if (!eglInitialize(display_, &major, &minor)) fail("eglInitialize failed");
    if (!eglBindAPI(EGL_OPENGL_API)) fail("EGL has no desktop OpenGL");
    const bool noConfig = epoxy_has_egl_extension(display_, "EGL_KHR_no_config_context");
    EGLConfig config = noConfig ? EGL_NO_CONFIG_KHR : chooseConfig(display_);
    if (!noConfig && config == nullptr) fail("no EGL config for OpenGL");
    const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5, EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                 EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    context_ = eglCreateContext(display_, config, EGL_NO_CONTEXT, attributes);
    if (context_ == EGL_NO_CONTEXT) fail("no OpenGL 4.5 core context");
    if (!epoxy_has_egl_extension(display_, "EGL_KHR_surfaceless_context")) {
        if (noConfig) config = chooseConfig(display_);
        const EGLint size[] = {EGL_WIDTH, 1, EGL_HEIGHT, 1, EGL_NONE};
        surface_ = config != nullptr ? eglCreatePbufferSurface(display_, config, size) : EGL_NO_SURFACE;
        if (surface_ == EGL_NO_SURFACE) fail("EGL can neither go surfaceless nor make a pbuffer");
    }
    if (!eglMakeCurrent(display_, surface_, surface_, context_)) fail("eglMakeCurrent failed");
    if (epoxy_gl_version() < 45) throw GlContextError("OpenGL 4.5 core is required; the context offers " + description());
}

EglContext::~EglContext() { release(); }

void EglContext::release() {
    if (display_ == EGL_NO_DISPLAY) return;
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (surface_ != EGL_NO_SURFACE) eglDestroySurface(display_, surface_);
    if (context_ != EGL_NO_CONTEXT) eglDestroyContext(display_, context_);
    eglTerminate(display_);
    display_ = EGL_NO_DISPLAY;
}

std::string EglContext::description() const {
    const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    const auto* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    return std::string(renderer ? renderer : "?") + ", " + (version ? version : "?");
}

}  // namespace mini
