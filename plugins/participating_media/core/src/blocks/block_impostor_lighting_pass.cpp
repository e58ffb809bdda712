// Blocks mode, camera side: the blocks' light per impostor texel (block_impostor_lighting_pass.h).
#include "blocks/block_impostor_lighting_pass.h"

#include "common/frame_blocks.h"
#include "common/lit_media_inputs.h"
#include "nimbus/gpu/fullscreen_pass.h"
#include "nimbus/gpu/pipeline_state.h"
#include "nimbus/media/impostor_atlas.h"

namespace nimbus::media {

inline constexpr GLint kLitSizeLocation = 0;    // block_impostor_lighting.vert uLitSize
inline constexpr GLint kFirstRankLocation = 2;  // block_impostor_lighting.vert uFirstRank

gpu::ProgramDesc blockImpostorLightingDesc(bool ownParticles) {
    gpu::ProgramDesc desc{.vertex = "media/blocks/block_impostor_lighting.vert", .fragment = "media/blocks/block_impostor_lighting.frag"};
    if (ownParticles) desc.defines.push_back("BLOCK_OWN_PARTICLES");
    return desc;
}

LocalLightPrograms& BlockImpostorLightingPass::programs(bool ownParticles) {
    std::unique_ptr<LocalLightPrograms>& programs = programs_[ownParticles ? 1 : 0];
    if (!programs) programs = std::make_unique<LocalLightPrograms>(blockImpostorLightingDesc(ownParticles));
    return *programs;
}

gpu::ResourceHandle BlockImpostorLightingPass::add(gpu::FrameGraph& graph, GraphFrame& context, const BlockImpostorAtlas& atlas,
                                                   std::vector<Run> runs, const BlockGpuBuffers& blocks, const ParticleGpuBuffer& particles,
                                                   const gpu::Texture* keep) {
    struct Lighting : LitMediaInputs {
        BlockImpostorReads atlas;
    };
    std::vector<std::pair<Run, const gpu::Program*>> draws;
    for (const Run& run : runs) draws.emplace_back(run, &programs(run.ownParticles).forLights(context.host.lights, context.multiple));
    // Two by two atlas texels to a lit texel (block_data.glsl litTile).
    const glm::ivec2 size = (atlas.size + (kTileAlignment - 1)) / kTileAlignment;
    const gpu::ResourceHandle kept = keep != nullptr ? graph.importTexture("block_impostor_lit", *keep) : gpu::ResourceHandle{};
    const auto& data = graph.addPass<Lighting>(
        "block_impostor_lighting",
        [&](gpu::PassBuilder& builder, Lighting& d) {
            d.media = kept.valid() ? builder.write(kept) : builder.create("block_impostor_lit", {GL_TEXTURE_2D, GL_RGBA32F, size.x, size.y, 1, 1});
            readLitMediaInputs(builder, context, d);
            d.atlas = readBlockImpostors(builder, atlas);
        },
        [this, draws, &context, &blocks, &particles, size](const gpu::PassResources& r, const Lighting& d) {
            const gpu::Framebuffer fbo = gpu::singleTargetFramebuffer(r.id(d.media), GL_RGBA32F);
            glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
            glViewport(0, 0, size.x, size.y);
            gpu::applyPipeline(gpu::PipelineState{});  // each texel written once: no blending
            context.blocks->bind();
            blocks.bind(0);
            particles.bindParticles();
            particles.bindLampNeighbourhoods();
            bindLitMediaInputs(r, d);
            bindBlockImpostors(r, d.atlas);
            glBindVertexArray(vertexArray_.id());
            for (const auto& [run, program] : draws) {
                glUseProgram(program->id());
                glProgramUniform2f(program->id(), kLitSizeLocation, static_cast<float>(size.x), static_cast<float>(size.y));
                glProgramUniform1i(program->id(), kFirstRankLocation, run.ranks.first);
                glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, run.ranks.count);
            }
        });
    return data.media;
}

}  // namespace nimbus::media
