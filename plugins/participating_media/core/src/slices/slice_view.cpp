#include "slices/slice_view.h"

#include <algorithm>

#include <glm/gtc/type_ptr.hpp>

namespace nimbus::media {

void attachSliceLayers(GLuint framebuffer, GLuint texture, int firstLayer, int count) {
    GLenum drawBuffers[8] = {GL_NONE, GL_NONE, GL_NONE, GL_NONE, GL_NONE, GL_NONE, GL_NONE, GL_NONE};
    for (int a = 0; a < count; ++a) {
        glNamedFramebufferTextureLayer(framebuffer, GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(a), texture, 0, firstLayer + a);
        drawBuffers[a] = GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(a);
    }
    glNamedFramebufferDrawBuffers(framebuffer, count, drawBuffers);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
}

void detachSliceLayers(GLuint framebuffer, int count) {
    for (int a = 0; a < count; ++a) glNamedFramebufferTexture(framebuffer, GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(a), 0, 0);
}

void bindSliceLayers(GLuint framebuffer, GLuint texture, const SliceView& view, bool clear) {
    const int attachments = std::min((view.slices + 3) / 4, 8);
    attachSliceLayers(framebuffer, texture, view.firstLayer, attachments);
    const float zero[4] = {0, 0, 0, 0};
    if (clear)
        for (int a = 0; a < attachments; ++a) glClearNamedFramebufferfv(framebuffer, GL_COLOR, a, zero);
}

void unbindSliceLayers(GLuint framebuffer, const SliceView& view) { detachSliceLayers(framebuffer, (view.slices + 3) / 4); }

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
