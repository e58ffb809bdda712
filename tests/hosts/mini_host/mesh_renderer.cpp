#include "mesh_renderer.h"

#include <glm/gtc/matrix_inverse.hpp>

#include "nimbus/gpu/shader_program.h"

namespace mini {
namespace gpu = nimbus::gpu;

gpu::ProgramDesc miniProgram(const char* vertex, const char* fragment) {
    gpu::ProgramDesc desc;
    desc.vertex = vertex;
    desc.fragment = fragment;
    desc.folder = MINI_HOST_SHADER_DIR;
    return desc;
}

MeshRenderer::MeshRenderer(const Scene& scene)
    : meshes_(scene),
      shadowProgram_(gpu::compileProgram(miniProgram("shadow.vert", "shadow.frag"))),
      compareSampler_(gpu::createSampler(GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE)),
      framebuffer_(gpu::createFramebuffer()) {
    // A lookup returns the lit fraction: stored depth ≥ reference (reversed Z: larger is nearer the light).
    glSamplerParameteri(compareSampler_.id(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glSamplerParameteri(compareSampler_.id(), GL_TEXTURE_COMPARE_FUNC, GL_GEQUAL);
    glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);  // reversed Z needs [0, 1] clip depth
}

const gpu::Program& MeshRenderer::opaqueProgram(bool mediaTransmittance) {
    auto it = opaquePrograms_.find(mediaTransmittance);
    if (it == opaquePrograms_.end()) {
        gpu::ProgramDesc desc = miniProgram("mesh.vert", "mesh.frag");
        if (mediaTransmittance) desc.defines.push_back("MEDIA_LIGHT_TRANSMITTANCE");
        it = opaquePrograms_.emplace(mediaTransmittance, gpu::compileProgram(desc)).first;
    }
    return it->second;
}

void MeshRenderer::renderShadows(const FrameInput& frame) {
    blocks_.upload(frame);
    int layers = 0;
    for (const auto& views : frame.shadowViews) layers += static_cast<int>(views.size());
    if (layers == 0 || frame.instances.empty()) {
        shadowMap_ = {};  // no views, or nothing to cast and nothing to receive
        return;
    }
    if (!shadowMap_ || shadowMap_.desc().depth != layers)
        shadowMap_ = gpu::Texture({GL_TEXTURE_2D_ARRAY, GL_DEPTH_COMPONENT32F, kShadowMapSize, kShadowMapSize, layers, 1});
    glUseProgram(shadowProgram_.id());
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
    glNamedFramebufferDrawBuffer(framebuffer_.id(), GL_NONE);
    glViewport(0, 0, kShadowMapSize, kShadowMapSize);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_GREATER);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(-1.5f, -2.0f);  // reversed Z: push stored depth away from the light (slope-scaled)
    int layer = 0;
    for (const auto& views : frame.shadowViews) {
        for (const auto& view : views) {
            glNamedFramebufferTextureLayer(framebuffer_.id(), GL_DEPTH_ATTACHMENT, shadowMap_.id(), 0, layer++);
            const float far = 0.0f;
            glClearNamedFramebufferfv(framebuffer_.id(), GL_DEPTH, 0, &far);
            glProgramUniformMatrix4fv(shadowProgram_.id(), 1, 1, GL_FALSE, &view.viewProjection[0][0]);
            drawInstances(frame, {shadowProgram_.id(), false});  // both faces: any triangle blocks light
        }
    }
    glDisable(GL_POLYGON_OFFSET_FILL);
    glNamedFramebufferTexture(framebuffer_.id(), GL_DEPTH_ATTACHMENT, 0, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void MeshRenderer::ensureTargets(int width, int height) {
    if (color_ && color_.desc().width == width && color_.desc().height == height) return;
    color_ = gpu::Texture({GL_TEXTURE_2D, GL_RGBA32F, width, height, 1, 1});
    depth_ = gpu::Texture({GL_TEXTURE_2D, GL_DEPTH_COMPONENT32F, width, height, 1, 1});
}

void MeshRenderer::renderOpaque(const FrameInput& frame, bool mediaTransmittance) {
    const GLuint program = opaqueProgram(mediaTransmittance).id();
    ensureTargets(frame.view.width, frame.view.height);
    const GLuint fbo = framebuffer_.id();
    glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT0, color_.id(), 0);
    glNamedFramebufferTexture(fbo, GL_DEPTH_ATTACHMENT, depth_.id(), 0);
    glNamedFramebufferDrawBuffer(fbo, GL_COLOR_ATTACHMENT0);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glViewport(0, 0, frame.view.width, frame.view.height);
    const glm::vec4 background(frame.environment.background, 1.0f);
    glClearNamedFramebufferfv(fbo, GL_COLOR, 0, &background[0]);
    const float far = frame.standardDepth ? 1.0f : 0.0f;  // reversed Z: 0 is infinitely far
    glClearNamedFramebufferfv(fbo, GL_DEPTH, 0, &far);

    glUseProgram(program);
    blocks_.bind();
    glBindTextureUnit(kShadowMapUnit, shadowMap_.id());
    glBindSampler(kShadowMapUnit, compareSampler_.id());
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(frame.standardDepth ? GL_LESS : GL_GREATER);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
    drawInstances(frame, {program, true});
    glBindSampler(kShadowMapUnit, 0);
    glDisable(GL_CULL_FACE);
    glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT0, 0, 0);
    glNamedFramebufferTexture(fbo, GL_DEPTH_ATTACHMENT, 0, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

// uModel (location 0) maps the mesh to camera-relative world: the translation loses the camera
// position in double before the matrix becomes float, so far-away scenes keep their precision.
void MeshRenderer::drawInstances(const FrameInput& frame, const DrawState& state) const {
    for (const MeshInstance& instance : frame.instances) {
        glm::dmat4 relative = instance.world;
        relative[3] -= glm::dvec4(frame.view.origin, 0.0);
        const glm::mat4 model(relative);
        glProgramUniformMatrix4fv(state.program, 0, 1, GL_FALSE, &model[0][0]);
        if (state.material) {
            const glm::mat3 normalMatrix(glm::inverseTranspose(glm::dmat3(instance.world)));
            glProgramUniformMatrix3fv(state.program, 1, 1, GL_FALSE, &normalMatrix[0][0]);
        }
        // A mirroring transform flips the winding: the front face follows the determinant's sign.
        glFrontFace(glm::determinant(glm::dmat3(instance.world)) < 0.0 ? GL_CW : GL_CCW);
        for (const GpuPrimitive& primitive : meshes_.primitives(instance.mesh)) {
            const Material& material = meshes_.material(primitive.material);
            if (state.material && !material.doubleSided) {
                glEnable(GL_CULL_FACE);
                glCullFace(GL_BACK);
            } else {
                glDisable(GL_CULL_FACE);
            }
            if (state.material) {
                glProgramUniform4fv(state.program, 2, 1, &material.baseColorFactor[0]);
                glProgramUniform2f(state.program, 3, material.metallicFactor, material.roughnessFactor);
                glProgramUniform3fv(state.program, 4, 1, &material.emissiveFactor[0]);
                const glm::vec3 forward(frame.view.forward);
                glProgramUniform4f(state.program, 5, forward.x, forward.y, forward.z, frame.view.orthographic ? 1.0f : 0.0f);
            }
            glBindVertexArray(primitive.vertexArray.id());
            glDrawElements(GL_TRIANGLES, primitive.indexCount, GL_UNSIGNED_INT, nullptr);
        }
    }
    glFrontFace(GL_CCW);
    glBindVertexArray(0);
}

}  // namespace mini
