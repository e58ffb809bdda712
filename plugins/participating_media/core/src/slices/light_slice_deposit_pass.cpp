// Light slices in deposit form, first pass: every (particle, slab) piece of every view additively
// into its slab's R32F layer (shaders/media/light_slice_deposit.*). light_slice_prefix_pass.cpp sums them.
#include <algorithm>

#include "slices/light_slice_deposit_pass.h"

#include <glm/gtc/type_ptr.hpp>

#include "nimbus/media/gpu_bindings.h"
#include "nimbus/gpu/shader_program.h"

namespace nimbus::media {

namespace {
constexpr GLint kFirstPieceLocation = 7;
constexpr GLint kFirstLayerLocation = 8;

// What light_slice_deposit.vert reads of a view: 0 view, 2 params (perspective, depth near/far,
// slices), 5 the view's projection.
void setDepositUniforms(GLuint program, const SliceView& v) {
    const glm::vec4 params(v.view.perspective ? 1.0f : 0.0f, v.view.depthNear, v.view.depthFar, static_cast<float>(v.slices));
    const glm::mat4 projection = v.view.viewProjection * glm::inverse(v.view.view);
    glProgramUniformMatrix4fv(program, 0, 1, GL_FALSE, glm::value_ptr(v.view.view));
    glProgramUniform4fv(program, 2, 1, glm::value_ptr(params));
    glProgramUniformMatrix4fv(program, 5, 1, GL_FALSE, glm::value_ptr(projection));
}

}  // namespace

LightSliceDepositPass::LightSliceDepositPass()
    : orthographic_(gpu::compileProgram({.vertex = "media/slices/light_slice_deposit.vert", .fragment = "media/slices/light_slice_deposit.frag"})),
      perspective_(gpu::compileProgram({.vertex = "media/slices/light_slice_deposit.vert",
                                        .fragment = "media/slices/light_slice_deposit.frag",
                                        .defines = {"LIGHT_PERSPECTIVE"}})) {}

bool LightSliceDepositPass::supported() { return epoxy_has_gl_extension("GL_ARB_shader_viewport_layer_array"); }

gpu::ResourceHandle LightSliceDepositPass::add(gpu::FrameGraph& graph, const std::vector<SliceView>& views, int resolution,
                                                  const ParticleGpuBuffer& buffer, std::vector<std::uint32_t> pieces,
                                                  std::vector<int> firstPiece) {
    int layers = 0;
    for (const SliceView& v : views) layers += v.slices;
    staging_ = std::move(pieces);
    struct Data {
        gpu::ResourceHandle slabs;
    };
    const auto& data = graph.addPass<Data>(
        "light_slice_deposit",
        [&](gpu::PassBuilder& builder, Data& d) {
            d.slabs = builder.create("light_slabs", {GL_TEXTURE_2D_ARRAY, GL_R32F, resolution, resolution, layers, 1});
        },
        [this, views, resolution, &buffer, firstPiece = std::move(firstPiece)](const gpu::PassResources& resources,
                                                                                        const Data& d) {
            const std::size_t bytes = std::max<std::size_t>(staging_.size(), 1) * sizeof(std::uint32_t);
            if (!pieces_ || capacity_ < bytes) {
                capacity_ = std::max(bytes, capacity_ * 3 / 2);
                pieces_ = gpu::createBuffer(capacity_, nullptr, GL_DYNAMIC_STORAGE_BIT);
            }
            if (!staging_.empty())
                glNamedBufferSubData(pieces_.id(), 0, static_cast<GLsizeiptr>(staging_.size() * sizeof(std::uint32_t)), staging_.data());
            gpu::Framebuffer fbo = gpu::createFramebuffer();
            glNamedFramebufferTexture(fbo.id(), GL_COLOR_ATTACHMENT0, resources.id(d.slabs), 0);  // layered: gl_Layer picks the slab
            glNamedFramebufferDrawBuffer(fbo.id(), GL_COLOR_ATTACHMENT0);
            glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
            const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
            glClearNamedFramebufferfv(fbo.id(), GL_COLOR, 0, zero);
            buffer.bindParticles();
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kSlicePiecesBinding, pieces_.id());
            gpu::applyPipeline(kSliceAdd);
            glBindVertexArray(vertexArray_.id());
            int firstLayer = 0;
            for (std::size_t v = 0; v < views.size(); ++v) {
                const GLuint program = views[v].view.perspective ? perspective_.id() : orthographic_.id();
                const int texels = sliceTexels(views[v], resolution);
                glViewport(0, 0, texels, texels);
                glUseProgram(program);
                setDepositUniforms(program, views[v]);
                glProgramUniform1i(program, kFirstPieceLocation, firstPiece[v]);
                glProgramUniform1i(program, kFirstLayerLocation, firstLayer);
                const GLsizei count = firstPiece[v + 1] - firstPiece[v];
                if (count > 0) glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, count);
                firstLayer += views[v].slices;
            }
        });
    return data.slabs;
}

}  // namespace nimbus::media
