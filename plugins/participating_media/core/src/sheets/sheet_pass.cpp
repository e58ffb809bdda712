// `sheets` mode's pass: per sheet, back to front, the slabs of the particles that reach into it
// are summed into the sheet buffer (additive: their order does not matter), then the sheet is
// composited over the media target as one layer. Two draws a sheet, on two framebuffers.
#include "sheets/sheet_pass.h"

#include "common/frame_blocks.h"
#include "common/kernel_table.h"
#include "common/lit_media_inputs.h"
#include "nimbus/gpu/frame_layout.h"
#include "nimbus/gpu/pipeline_state.h"

namespace nimbus::media {

namespace {
constexpr GLint kFullResScaleLocation = 1;   // sheet_splats.frag, sheet_exact.frag uFullResScale
constexpr GLint kSheetLocation = 2;          // sheet_splats.*, sheet_exact.* uSheet
constexpr GLint kFirstRankLocation = 3;      // sheet_splats.vert, sheet_exact.vert uFirstRank
constexpr GLint kFragmentSunLocation = 7;    // particle_light_layout.glsl uFragmentSun
constexpr GLint kFragmentLampsLocation = 8;  // particle_light_layout.glsl uFragmentLamps
constexpr gpu::PipelineState kSheetSum = gpu::PipelineState::blending(gpu::kAdditive);
}  // namespace

SheetPass::SheetPass() : composite_(gpu::compileProgram(sheetCompositeDesc())), kernelTable_(createKernelTable()) {}

gpu::ProgramDesc sheetSplatDesc(bool lamps, bool constant, bool multiple, bool pointLamps) {
    gpu::ProgramDesc desc{.vertex = "media/sheets/sheet_splats.vert", .fragment = "media/sheets/sheet_splats.frag"};
    if (lamps) desc.defines.push_back("MEDIA_FRAGMENT_LAMPS");
    if (lamps && pointLamps) desc.defines.push_back("MEDIA_POINT_LAMPS");
    if (constant) desc.defines.push_back("SPLAT_CONSTANT");
    if (multiple) desc.defines.push_back("MEDIA_MULTIPLE");
    return desc;
}

gpu::ProgramDesc sheetExactDesc() {
    return {.vertex = "media/sheets/sheet_exact.vert", .fragment = "media/sheets/sheet_exact.frag", .defines = {"MEDIA_LAYER_LIGHT"}};
}

gpu::ProgramDesc sheetCompositeDesc() { return {.vertex = "fullscreen.vert", .fragment = "media/sheets/sheet_composite.frag"}; }

const gpu::Program& SheetPass::splatProgram(bool lamps, bool constant, bool multiple, bool pointLamps) {
    pointLamps = lamps && pointLamps;
    gpu::Program& p = splatPrograms_.at((lamps ? 1 : 0) + (constant ? 2 : 0) + (multiple ? 4 : 0) + (pointLamps ? 8 : 0));
    if (!p) p = gpu::compileProgram(sheetSplatDesc(lamps, constant, multiple, pointLamps));
    return p;
}

gpu::ResourceHandle SheetPass::add(gpu::FrameGraph& graph, GraphFrame& context, const ParticleGpuBuffer& buffer,
                                   const ParticleLightingPass* lighting, const SheetPlan& plan, bool constant,
                                   const FragmentLamps& lamps, const MediaTarget& target) {
    const bool perFragment = lighting == nullptr;
    if (perFragment && !exact_) exact_ = std::make_unique<LocalLightPrograms>(sheetExactDesc());
    const gpu::Program& slabs =
        perFragment ? exact_->forLights(context.host.lights, context.multiple) : splatProgram(lamps.lamps[0] >= 0, constant, context.multiple, lamps.allPoint);
    // The splats read the slices and the shadow map only for their per-fragment lamps.
    const bool lit = perFragment || lamps.lamps[0] >= 0;
    struct Data {
        gpu::ResourceHandle media, sheet, depth, slices, shadowMap;
    };
    const glm::ivec2 size = target.size;
    const auto& data = graph.addPass<Data>(
        "media_sheets",
        [&](gpu::PassBuilder& builder, Data& d) {
            d.media = builder.create(target.name, {GL_TEXTURE_2D, GL_RGBA32F, size.x, size.y, 1, 1});
            d.sheet = builder.create("media_sheet", {GL_TEXTURE_2D, GL_RGBA32F, size.x, size.y, 1, 1});
            d.depth = builder.read(context.sceneDepth);
            if (lit && context.slices.valid()) d.slices = builder.read(context.slices);
            if (lit && context.shadowMap.valid()) d.shadowMap = builder.read(context.shadowMap);
        },
        [this, &slabs, &context, &buffer, lighting, &plan, lamps, size, scale = target.fullResScale](const gpu::PassResources& resources,
                                                                                                 const Data& d) {
            const gpu::Framebuffer media = bindClearedMediaTarget(resources.id(d.media), size);
            const gpu::Framebuffer sheet = gpu::createFramebuffer();
            glNamedFramebufferTexture(sheet.id(), GL_COLOR_ATTACHMENT0, resources.id(d.sheet), 0);
            glNamedFramebufferDrawBuffer(sheet.id(), GL_COLOR_ATTACHMENT0);
            context.blocks->bind();
            buffer.bindParticles();
            buffer.bindOrder();
            glBindTextureUnit(kSceneDepthUnit, resources.id(d.depth));
            if (d.slices.valid()) glBindTextureUnit(kSlicesUnit, resources.id(d.slices));
            if (d.shadowMap.valid()) glBindTextureUnit(kShadowDepthUnit, resources.id(d.shadowMap));
            glProgramUniform2f(slabs.id(), kFullResScaleLocation, scale.x, scale.y);
            if (lighting != nullptr) {
                lighting->bind();
                glBindTextureUnit(kKernelTableUnit, kernelTable_.id());
                glProgramUniform1i(slabs.id(), kFragmentSunLocation, lamps.sun);
                if (lamps.lamps[0] >= 0) glProgramUniform1iv(slabs.id(), kFragmentLampsLocation, kMaxFragmentLamps, lamps.lamps.data());
            } else {
                buffer.bindLampNeighbourhoods();
            }
            glBindVertexArray(vertexArray_.id());
            const float empty[4] = {0.0f, 0.0f, 0.0f, 0.0f};
            for (const Sheet& s : plan.sheets) {
                glClearNamedFramebufferfv(sheet.id(), GL_COLOR, 0, empty);
                glBindFramebuffer(GL_FRAMEBUFFER, sheet.id());
                glUseProgram(slabs.id());
                glProgramUniform2f(slabs.id(), kSheetLocation, s.nearDepth, s.farDepth);
                glProgramUniform1i(slabs.id(), kFirstRankLocation, static_cast<GLint>(s.firstRank));
                gpu::applyPipeline(kSheetSum);
                glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(s.ranks));
                glBindFramebuffer(GL_FRAMEBUFFER, media.id());
                glUseProgram(composite_.id());
                glBindTextureUnit(kSheetUnit, resources.id(d.sheet));
                gpu::applyPipeline(kMediaOver);
                glDrawArrays(GL_TRIANGLES, 0, 3);
                glBindTextureUnit(kSheetUnit, 0);  // the next sheet's slabs render into it
            }
        });
    return data.media;
}

}  // namespace nimbus::media
