#include "viewport_display.h"

namespace nimbus::sandbox::editor {

ViewportDisplay::ViewportDisplay()
    : program_(gpu::compileProgram({.vertex = "fullscreen.vert", .fragment = "editor/viewport_display.frag"})),
      framebuffer_(gpu::createFramebuffer()),
      vertexArray_(gpu::createVertexArray()) {}

void ViewportDisplay::encode(const gpu::Texture& radiance) {
    const int width = radiance.desc().width, height = radiance.desc().height;
    if (!display_ || display_.desc().width != width || display_.desc().height != height) {
        display_ = gpu::Texture({.format = GL_RGBA8, .width = width, .height = height});
        glNamedFramebufferTexture(framebuffer_.id(), GL_COLOR_ATTACHMENT0, display_.id(), 0);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
    glViewport(0, 0, width, height);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glUseProgram(program_.id());
    glBindTextureUnit(0, radiance.id());
    glBindVertexArray(vertexArray_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace nimbus::sandbox::editor
