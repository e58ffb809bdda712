#include "slices/slice_view.h"

#include <algorithm>

#include <glm/gtc/type_ptr.hpp>

namespace nimbus::media {

void bindSliceLayers(GLuint framebuffer, GLuint texture, const SliceView& view, bool clear) {
    const int attachments = std::min((view.slices + 3) / 4, 8);
    GLenum drawBuffers[8] = {GL_NONE, GL_NONE, GL_NONE, GL_NONE, GL_NONE, GL_NONE, GL_NONE, GL_NONE};
    for (int a = 0; a < attachments; ++a) {
        glNamedFramebufferTextureLayer(framebuffer, GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(a), texture, 0, view.firstLayer + a);
        drawBuffers[a] = GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(a);
    }
    glNamedFramebufferDrawBuffers(framebuffer, attachments, drawBuffers);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    const float zero[4] = {0, 0, 0, 0};
    if (clear)
        for (int a = 0; a < attachments; ++a) glClearNamedFramebufferfv(framebuffer, GL_COLOR, a, zero);
}

void unbindSliceLayers(GLuint framebuffer, const SliceView& view) {
    for (int a = 0; a < (view.slices + 3) / 4; ++a)
        glNamedFramebufferTexture(framebuffer, GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(a), 0, 0);
}

void setSliceViewUniforms(GLuint program, const SliceView& v, int resolution) {
    const glm::vec4 params(v.view.perspective ? 1.0f : 0.0f, v.view.depthNear, v.view.depthFar, static_cast<float>(v.slices));
    const glm::vec2 size(static_cast<float>(resolution));
    glProgramUniformMatrix4fv(program, 0, 1, GL_FALSE, glm::value_ptr(v.view.view));
    glProgramUniform4fv(program, 2, 1, glm::value_ptr(params));
    glProgramUniform2fv(program, 3, 1, glm::value_ptr(v.view.halfExtent));
    glProgramUniform2fv(program, 4, 1, glm::value_ptr(size));
    glProgramUniform3fv(program, 6, 1, glm::value_ptr(v.lightOrigin));
}

void setParticleSliceUniforms(GLuint program, const SliceView& v, int resolution) {
    setSliceViewUniforms(program, v, resolution);
    const glm::mat4 projection = v.view.viewProjection * glm::inverse(v.view.view);
    glProgramUniformMatrix4fv(program, 5, 1, GL_FALSE, glm::value_ptr(projection));
}

void setAdditiveSliceState(int resolution) {
    glViewport(0, 0, resolution, resolution);
    gpu::applyPipeline(kSliceAdd);
}

}  // namespace nimbus::media
