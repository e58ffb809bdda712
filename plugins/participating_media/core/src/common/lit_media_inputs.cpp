#include "common/lit_media_inputs.h"

#include "nimbus/media/gpu_bindings.h"

namespace nimbus::media {

gpu::ResourceHandle declareMediaTarget(gpu::PassBuilder& builder, const MediaTarget& target) {
    if (target.over.valid()) return builder.write(target.over);
    return builder.create(target.name, {GL_TEXTURE_2D, GL_RGBA32F, target.size.x, target.size.y, 1, 1});
}

void declareLitMediaInputs(gpu::PassBuilder& builder, const GraphFrame& context, const MediaTarget& target, LitMediaInputs& d) {
    d.media = declareMediaTarget(builder, target);
    readLitMediaInputs(builder, context, d);
}

void readLitMediaInputs(gpu::PassBuilder& builder, const GraphFrame& context, LitMediaInputs& d) {
    d.depth = builder.read(context.sceneDepth);
    if (context.shadowMap.valid()) d.shadowMap = builder.read(context.shadowMap);
    if (context.slices.valid()) d.slices = builder.read(context.slices);
}

void bindLitMediaInputs(const gpu::PassResources& resources, const LitMediaInputs& d) {
    glBindTextureUnit(kSceneDepthUnit, resources.id(d.depth));
    if (d.shadowMap.valid()) glBindTextureUnit(kShadowDepthUnit, resources.id(d.shadowMap));
    if (d.slices.valid()) glBindTextureUnit(kSlicesUnit, resources.id(d.slices));
}

namespace {

gpu::Framebuffer bindTarget(GLuint texture, glm::ivec2 size) {
    gpu::Framebuffer fbo = gpu::createFramebuffer();
    glNamedFramebufferTexture(fbo.id(), GL_COLOR_ATTACHMENT0, texture, 0);
    glNamedFramebufferDrawBuffer(fbo.id(), GL_COLOR_ATTACHMENT0);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
    glViewport(0, 0, size.x, size.y);
    return fbo;
}

}  // namespace

gpu::Framebuffer bindClearedMediaTarget(GLuint texture, glm::ivec2 size) {
    gpu::Framebuffer fbo = bindTarget(texture, size);
    const float clear[4] = {0.0f, 0.0f, 0.0f, 1.0f};  // no radiance, full transmittance
    glClearNamedFramebufferfv(fbo.id(), GL_COLOR, 0, clear);
    return fbo;
}

gpu::Framebuffer bindMediaTarget(GLuint texture, const MediaTarget& target) {
    return target.over.valid() ? bindTarget(texture, target.size) : bindClearedMediaTarget(texture, target.size);
}

}  // namespace nimbus::media
