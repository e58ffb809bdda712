// Mesh shadow maps: every light view renders all meshes' depth into its layer of one D32F array.
// Both faces are drawn (any triangle blocks light, as in the reference); a slope-scaled polygon
// offset plus the lookup's normal offset keep lit surfaces from shadowing themselves. MASK
// materials cut their texels away (the same alpha test as the opaque pass), so a cutout casts the
// shadow of what is left of it, on meshes and on the medium alike. A point light's faces are drawn
// in the first pointShadowSize texels of their layers' sides (the lookups scale into that corner);
// only it and the one texel beyond it, which a lookup's bilinear footprint weighs 0, are cleared.
#include <algorithm>

#include "passes.h"

#include "material_binding.h"

#include "nimbus/gpu/frame_layout.h"
#include "nimbus/gpu/shader_program.h"

namespace nimbus::render {

ShadowPass::ShadowPass() {
    compareSampler_ = gpu::createSampler(GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(compareSampler_.id(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glSamplerParameteri(compareSampler_.id(), GL_TEXTURE_COMPARE_FUNC, GL_GEQUAL);
}

const gpu::Program& ShadowPass::program(unsigned features) {
    auto it = programs_.find(features);
    if (it == programs_.end())
        it = programs_.emplace(features, gpu::compileProgram({.vertex = "shadow_depth.vert", .fragment = "shadow_depth.frag",
                                                              .defines = featureDefines(features)})).first;
    return it->second;
}

void ShadowPass::add(FrameGraph& graph, FrameContext& context) {
    int layers = 0;
    for (const auto& views : context.shadowViews) layers += static_cast<int>(views.size());
    if (layers == 0 || context.input.instances.empty()) return;  // nothing casts: no shadow map at all
    const int size = context.settings.shadowMapSize;

    struct Data {
        ResourceHandle map;
    };
    const auto& data = graph.addPass<Data>(
        "shadow_maps",
        [&](PassBuilder& builder, Data& d) {
            d.map = builder.create("shadow_maps", {GL_TEXTURE_2D_ARRAY, GL_DEPTH_COMPONENT32F, size, size, layers, 1});
        },
        [this, &context, size](const PassResources& resources, const Data& d) {
            gpu::Framebuffer fbo = gpu::createFramebuffer();
            // Reversed Z; the offset pushes stored depth away from the light.
            gpu::applyPipeline({.depth = {.test = true, .compare = GL_GREATER, .write = true},
                                .polygonOffset = true,
                                .offsetFactor = -1.5f,
                                .offsetUnits = -2.0f});
            int layer = 0;
            const int pointFaceSize = pointShadowSize(context.settings);
            for (std::size_t light = 0; light < context.shadowViews.size(); ++light) {
                const int side = gpu::shadowViewSide(punctualLight(context.input.lights[light]).kind, size, pointFaceSize);
                glViewport(0, 0, side, side);
                for (const auto& view : context.shadowViews[light]) {
                    glNamedFramebufferTextureLayer(fbo.id(), GL_DEPTH_ATTACHMENT, resources.id(d.map), 0, layer++);
                    glNamedFramebufferDrawBuffer(fbo.id(), GL_NONE);
                    glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
                    const float clearDepth = 0.0f;
                    glEnable(GL_SCISSOR_TEST);
                    glScissor(0, 0, std::min(side + 1, size), std::min(side + 1, size));
                    glClearNamedFramebufferfv(fbo.id(), GL_DEPTH, 0, &clearDepth);
                    glDisable(GL_SCISSOR_TEST);
                    auto pick = [this, &view](const GpuMaterial& material, const GpuPrimitive& primitive) {
                        const unsigned features = shadowFeatures(materialFeatures(material, primitive));
                        const GLuint id = program(features).id();
                        glProgramUniformMatrix4fv(id, 1, 1, GL_FALSE, &view.viewProjection[0][0]);
                        return std::make_pair(id, features);
                    };
                    drawInstances(context, {.program = pick});
                }
            }

        });
    context.shadowMap = data.map;
}

}  // namespace nimbus::render
