#include "viewport_display.h"

namespace nimbus::sandbox::editor {

ViewportDisplay::ViewportDisplay()
    : pass_("editor/viewport_display.frag"), framebuffer_(gpu::createFramebuffer()) {}

void ViewportDisplay::encode(const gpu::Texture& radiance) {
    const int width = radiance.desc().width, height = radiance.desc().height;
    if (!display_ || display_.desc().width != width || display_.desc().height != height) {
        display_ = gpu::Texture({.format = GL_RGBA8, .width = width, .height = height});
        glNamedFramebufferTexture(framebuffer_.id(), GL_COLOR_ATTACHMENT0, display_.id(), 0);
    }
    glBindTextureUnit(0, radiance.id());
    pass_.draw(framebuffer_.id(), {width, height});
}

}  // namespace nimbus::sandbox::editor
