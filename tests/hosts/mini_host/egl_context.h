#pragma once
// A headless OpenGL 4.5 core context through EGL, current on the calling thread for its lifetime.
// Surfaceless (EGL_MESA_platform_surfaceless) when the driver offers it, else the default display;
// a 1×1 pbuffer only when the driver cannot make a context current without a surface. Rendering
// goes to framebuffer objects.
#include <stdexcept>
#include <string>

#include <epoxy/egl.h>

namespace mini {

class GlContextError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class EglContext {
public:
    EglContext();  // throws GlContextError
    ~EglContext();
    EglContext(const EglContext&) = delete;
    EglContext& operator=(const EglContext&) = delete;

    std::string description() const;  // "GL_RENDERER, GL_VERSION"

private:
    void create();
    void release();

    EGLDisplay display_ = EGL_NO_DISPLAY;
    EGLContext context_ = EGL_NO_CONTEXT;
    EGLSurface surface_ = EGL_NO_SURFACE;
};

}  // namespace mini
