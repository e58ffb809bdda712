#include "compose.h"

#include <cstring>
#include <stdexcept>

#include <OpenImageIO/imageio.h>

#include "mesh_renderer.h"
#include "nimbus/gpu/shader_program.h"

namespace mini {
namespace gpu = nimbus::gpu;

Composer::Composer()
    : program_(gpu::compileProgram(miniProgram("fullscreen.vert", "compose.frag"))),
      clamped_(gpu::createSampler(GL_NEAREST, GL_NEAREST, GL_CLAMP_TO_EDGE)),
      emptyVertexArray_(gpu::createVertexArray()),
      framebuffer_(gpu::createFramebuffer()) {}

void Composer::compose(GLuint opaqueColor, GLuint sceneDepth, const gpu::View& view, bool standardDepth, const MediaLayerRef* layer) {
    const int width = view.width, height = view.height;
    if (!output_ || output_.desc().width != width || output_.desc().height != height)
        output_ = gpu::Texture({GL_TEXTURE_2D, GL_RGBA32F, width, height, 1, 1});
    glNamedFramebufferTexture(framebuffer_.id(), GL_COLOR_ATTACHMENT0, output_.id(), 0);
    glNamedFramebufferDrawBuffer(framebuffer_.id(), GL_COLOR_ATTACHMENT0);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
    glViewport(0, 0, width, height);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    glUseProgram(program_.id());
    const bool media = layer != nullptr && layer->color != 0;
    const int mode = !media ? 0 : layer->width == width && layer->height == height ? 1 : 2;
    glProgramUniform1i(program_.id(), 0, mode);
    glBindTextureUnit(0, opaqueColor);
    glBindTextureUnit(1, media ? layer->color : 0);
    if (mode == 2) {
        glBindTextureUnit(2, layer->depthUsed);
        glBindSampler(2, clamped_.id());
        glBindTextureUnit(3, sceneDepth);
        glProgramUniform2f(program_.id(), 1, static_cast<float>(layer->width) / static_cast<float>(width),
                           static_cast<float>(layer->height) / static_cast<float>(height));
        glProgramUniform1f(program_.id(), 2, layer->edgeThreshold);
        const glm::vec2 ab = standardDepth ? glm::vec2(view.znear, view.zfar) : view.depthLinearization();
        glProgramUniform4f(program_.id(), 3, ab.x, ab.y, view.orthographic ? 1.0f : 0.0f, standardDepth ? 1.0f : 0.0f);
        // No edges: an empty rect, which no pixel is inside.
        glBindTextureUnit(4, layer->edges);
        const glm::ivec4 rect = layer->edges != 0 ? layer->edgeRect : glm::ivec4(0);
        glProgramUniform4i(program_.id(), 4, rect.x, rect.y, rect.z, rect.w);
    }
    glBindVertexArray(emptyVertexArray_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glBindSampler(2, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

std::vector<float> readRgbaTopDown(GLuint texture, int width, int height) {
    const std::size_t row = static_cast<std::size_t>(width) * 4;
    std::vector<float> bottomUp(row * static_cast<std::size_t>(height));
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTextureImage(texture, 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(bottomUp.size() * sizeof(float)), bottomUp.data());
    std::vector<float> topDown(bottomUp.size());
    for (std::size_t y = 0; y < static_cast<std::size_t>(height); ++y)
        std::memcpy(&topDown[y * row], &bottomUp[(static_cast<std::size_t>(height) - 1 - y) * row], row * sizeof(float));
    return topDown;
}

void writeExr(const std::filesystem::path& file, int width, int height, const std::vector<float>& rgba) {
    const std::string name = file.string();
    auto out = OIIO::ImageOutput::create(name);
    if (!out) throw std::runtime_error(name + ": no image writer (" + OIIO::geterror() + ")");
    OIIO::ImageSpec spec(width, height, 4, OIIO::TypeDesc::FLOAT);
    spec.attribute("compression", "zip");
    if (!out->open(name, spec)) throw std::runtime_error(name + ": cannot open for writing: " + out->geterror());
    if (!out->write_image(OIIO::TypeDesc::FLOAT, rgba.data()) || !out->close())
        throw std::runtime_error(name + ": write failed: " + out->geterror());
}

}  // namespace mini
