// A window with a GL 4.5 core context through GLFW (the editor). libepoxy resolves GL entry points
// through GLX or EGL, whichever GLFW made current.
#include <epoxy/gl.h>

#include <GLFW/glfw3.h>

#include <string>

#include "context_backends.h"
#include "nimbus/base/error.h"

namespace nimbus::gpu {
namespace {

std::string glfwErrorText() {
    const char* description = nullptr;
    glfwGetError(&description);
    return description ? description : "unknown GLFW error";
}

class GlfwContext final : public Context {
public:
    GlfwContext(const ContextDesc& desc, bool debug) {
        if (!glfwInit()) throw SystemError("GLFW could not initialise (is a display available?): " + glfwErrorText());
        glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
        glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
        glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
        glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, debug ? GLFW_TRUE : GLFW_FALSE);
        const int width = desc.width > 0 ? desc.width : 1280;
        const int height = desc.height > 0 ? desc.height : 720;
        window_ = glfwCreateWindow(width, height, desc.title ? desc.title : "Nimbus", nullptr, nullptr);
        if (!window_) {
            std::string reason = glfwErrorText();
            glfwTerminate();
            throw SystemError("no GL 4.5 core window: " + reason);
        }
        makeCurrent();
        glfwSwapInterval(1);
    }

    ~GlfwContext() override {
        glfwDestroyWindow(window_);
        glfwTerminate();
    }

    void makeCurrent() override { glfwMakeContextCurrent(window_); }
    void swapBuffers() override { glfwSwapBuffers(window_); }
    bool shouldClose() const override { return glfwWindowShouldClose(window_) != 0; }
    void pollEvents() override { glfwPollEvents(); }
    void framebufferSize(int& width, int& height) const override { glfwGetFramebufferSize(window_, &width, &height); }
    void* nativeWindow() const override { return window_; }

private:
    GLFWwindow* window_ = nullptr;
};

}  // namespace

std::unique_ptr<Context> createGlfwContext(const ContextDesc& desc, bool debug) {
    return std::make_unique<GlfwContext>(desc, debug);
}

}  // namespace nimbus::gpu
