// Blocks mode, camera side: the blocks composited back to front over their screen rectangles from
// the camera's impostor atlas (block_impostor_pass.cpp), shaders/media/block_composite.*.
#include "blocks/block_composite_pass.h"

#include <algorithm>

#include "common/lit_media_inputs.h"
#include "common/frame_blocks.h"
#include "nimbus/media/gpu_bindings.h"
#include "nimbus/gpu/frame_layout.h"
#include "nimbus/gpu/shader_program.h"

namespace nimbus::media {

inline constexpr GLint kFirstRankLocation = 2;  // block_composite.vert uFirstRank
inline constexpr GLint kSeamPartLocation = 3;   // block_composite.frag uSeamPart
inline constexpr GLint kSeamCellLocation = 5;   // block_composite.frag uSeamCell
inline constexpr GLint kFullResScaleLocation = 1;  // block_composite.frag uFullResScale
inline constexpr GLint kFragOffsetLocation = 6;    // block_composite.frag uFragOffset

BlockCompositePass::BlockCompositePass() { programs(kBlockPlain); }

LocalLightPrograms& BlockCompositePass::programs(std::uint8_t build) {
    std::unique_ptr<LocalLightPrograms>& programs = programs_[build & 15];
    if (!programs) programs = std::make_unique<LocalLightPrograms>(blockCompositeDesc(build));
    return *programs;
}

gpu::ProgramDesc blockCompositeDesc(std::uint8_t build) {
    gpu::ProgramDesc desc{.vertex = "media/blocks/block_composite.vert", .fragment = "media/blocks/block_composite.frag"};
    if (build & kBlockExactCut) desc.defines.push_back("BLOCK_EXACT_CUT");
    if (build & kBlockOwnParticles) desc.defines.push_back("BLOCK_OWN_PARTICLES");
    if (build & kBlockExactShading) desc.defines.push_back("BLOCK_EXACT_SHADING");
    if (build & kBlockLitImpostor) desc.defines.push_back("BLOCK_LIT_IMPOSTOR");
    return desc;
}

namespace {

std::vector<BlockCompositePass::Run> buildRuns(const std::vector<std::uint32_t>& backToFront, const std::vector<std::uint8_t>& builds) {
    std::vector<BlockCompositePass::Run> runs;
    for (std::size_t r = 0; r < backToFront.size(); ++r) {
        const std::uint8_t build = builds[backToFront[r]] & 15;
        if (runs.empty() || build != runs.back().build) runs.push_back({{static_cast<GLint>(r), 0}, build});
        ++runs.back().ranks.count;
    }
    return runs;
}

// A seam run's two draws: smoothly where the stencil is 0, exactly where it is 1 (read only).
gpu::PipelineState drawState(GLint seamPart) {
    gpu::PipelineState state = kMediaOver;
    if (seamPart == 0) return state;
    state.stencil = {.test = true, .compare = GL_EQUAL, .reference = seamPart == 2 ? 1 : 0, .readMask = 0xFF, .writeMask = 0x00};
    return state;
}

}  // namespace

// With seamOnly, the mask says where the blocks a mesh comes near are cut, and an exactly shaded
// run is drawn twice: smoothly off the seam, then exactly near it (the mask pass's stencil says
// which texels each draw shades). At each texel one of the two draws writes every block of the
// run, so the back-to-front order holds.
BlockCompositePass::Seam BlockCompositePass::addSeamPasses(gpu::FrameGraph& graph, GraphFrame& context, const std::vector<Run>& runs,
                                                           bool seamOnly, const BlockGpuBuffers& blocks, const BlockImpostorAtlas& atlas,
                                                           const MediaTarget& target, int cell) {
    std::vector<BlockRankRun> cutRuns;
    bool seamRuns = false;
    for (const Run& run : runs) {
        if (run.build & kBlockExactCut) cutRuns.push_back(run.ranks);
        seamRuns = seamRuns || (run.build & kBlockExactShading);
    }
    Seam seam;
    if (!seamOnly || !seamRuns || cutRuns.empty()) return seam;
    if (!seamMask_) seamMask_ = std::make_unique<BlockSeamMaskPass>();
    if (!seamStencil_) seamStencil_ = std::make_unique<BlockSeamStencilPass>();
    seam.mask = seamMask_->add(graph, context, std::move(cutRuns), blocks, atlas.depths, target, cell);
    seam.stencil = seamStencil_->add(graph, seam.mask, target, cell);
    return seam;
}

std::vector<BlockCompositePass::Draw> BlockCompositePass::edgeDraws(const std::vector<Light>& lights, bool multiple) {
    std::vector<Draw> draws;
    for (const Run& run : frame_.runs) {
        const bool exact = (run.build & kBlockExactShading) != 0;
        const auto build = static_cast<std::uint8_t>(exact ? run.build & ~kBlockLitImpostor : run.build);
        draws.push_back({run.ranks, &programs(build).forLights(lights, multiple), 0});
    }
    return draws;
}

// The blocks whose light is read from their impostor texels have it shaded there first, unless an
// earlier frame's is read again.
gpu::ResourceHandle BlockCompositePass::addLighting(gpu::FrameGraph& graph, GraphFrame& context, const std::vector<Run>& runs,
                                                    const CameraImpostors& impostors, const BlockGpuBuffers& blocks,
                                                    const ParticleGpuBuffer& particles) {
    std::vector<BlockImpostorLightingPass::Run> lit;
    for (const Run& run : runs)
        if (run.build & kBlockLitImpostor) lit.push_back({run.ranks, (run.build & kBlockOwnParticles) != 0});
    if (lit.empty()) return {};
    if (impostors.lit.reused.valid()) return impostors.lit.reused;
    if (!lighting_) lighting_ = std::make_unique<BlockImpostorLightingPass>();
    return lighting_->add(graph, context, impostors.atlas, std::move(lit), blocks, particles, impostors.lit.keep);
}

std::vector<BlockCompositePass::Draw> BlockCompositePass::planDraws(const std::vector<Run>& runs, bool seamOnly, bool seam,
                                                                    const std::vector<Light>& lights, bool multiple) {
    std::vector<Draw> draws;
    for (const Run& run : runs) {
        // The exact shading is per pixel; the smooth one reads the texels' light where they hold it.
        const auto smooth = static_cast<std::uint8_t>(run.build & ~kBlockExactShading);
        const auto exact = static_cast<std::uint8_t>(run.build & ~kBlockLitImpostor);
        if (!seamOnly || !(run.build & kBlockExactShading)) {
            draws.push_back({run.ranks, &programs(run.build & kBlockExactShading ? exact : run.build).forLights(lights, multiple), 0});
        } else if (seam) {
            draws.push_back({run.ranks, &programs(smooth).forLights(lights, multiple), 1});
            draws.push_back({run.ranks, &programs(exact).forLights(lights, multiple), 2});
        } else {  // no block a mesh comes near: no seam
            draws.push_back({run.ranks, &programs(smooth).forLights(lights, multiple), 0});
        }
    }
    return draws;
}

gpu::ResourceHandle BlockCompositePass::add(gpu::FrameGraph& graph, GraphFrame& context, const CameraImpostors& impostors,
                                            const std::vector<std::uint32_t>& backToFront, const std::vector<std::uint8_t>& builds,
                                            bool seamOnly, const BlockGpuBuffers& blocks, const ParticleGpuBuffer& particles,
                                            const MediaTarget& target) {
    const int w = target.size.x, h = target.size.y;
    const std::vector<Run> runs = buildRuns(backToFront, builds);
    const int seamCell = seamMaskCell(target.size);
    const Seam seam = addSeamPasses(graph, context, runs, seamOnly, blocks, impostors.atlas, target, seamCell);
    const std::vector<Draw> draws = planDraws(runs, seamOnly, seam.mask.valid(), context.host.lights, context.multiple);
    frame_ = {.atlas = impostors.atlas, .lit = addLighting(graph, context, runs, impostors, blocks, particles), .runs = runs};
    const auto& data = graph.addPass<Inputs>(
        "media_blocks",
        [&](gpu::PassBuilder& builder, Inputs& d) {
            declareLitMediaInputs(builder, context, target, d);
            readInputs(builder, d);
            if (seam.mask.valid()) {
                d.seamMask = builder.read(seam.mask);
                d.seamStencil = builder.read(seam.stencil);
            }
        },
        [this, draws, &context, &blocks, &particles, w, h, seamCell, scale = target.fullResScale](const gpu::PassResources& r,
                                                                                                 const Inputs& d) {
            const gpu::Framebuffer fbo = bindClearedMediaTarget(r.id(d.media), {w, h});
            if (d.seamStencil.valid()) glNamedFramebufferTexture(fbo.id(), GL_DEPTH_STENCIL_ATTACHMENT, r.id(d.seamStencil), 0);
            for (const Draw& draw : draws) glProgramUniform1i(draw.program->id(), kSeamCellLocation, seamCell);
            bindInputs(r, d, context, blocks, particles);
            if (d.seamMask.valid()) glBindTextureUnit(kSeamMaskUnit, r.id(d.seamMask));
            drawRuns(draws, scale, glm::vec2(0.0f), nullptr);
        });
    return data.media;
}

void BlockCompositePass::readInputs(gpu::PassBuilder& builder, Inputs& d) const {
    d.atlas = readBlockImpostors(builder, frame_.atlas);
    if (frame_.lit.valid()) d.lit = builder.read(frame_.lit);
}

void BlockCompositePass::bindInputs(const gpu::PassResources& r, const Inputs& d, const GraphFrame& context, const BlockGpuBuffers& blocks,
                                    const ParticleGpuBuffer& particles) const {
    context.blocks->bind();
    blocks.bind(0);
    particles.bindParticles();  // the listed particles around each lamp (lamp_neighbourhood.glsl)
    particles.bindLampNeighbourhoods();
    bindLitMediaInputs(r, d);
    bindBlockImpostors(r, d.atlas);
    if (d.lit.valid()) glBindTextureUnit(kImpostorLitUnit, r.id(d.lit));
}

// `scale` and `offset` map the target's texels to full-resolution pixels (block_composite.frag);
// `edges`: the state every draw takes instead of its own (the edges' stencil test).
void BlockCompositePass::drawRuns(const std::vector<Draw>& draws, glm::vec2 scale, glm::vec2 offset, const gpu::PipelineState* edges) const {
    glBindVertexArray(vertexArray_.id());
    for (const Draw& draw : draws) {
        const GLuint program = draw.program->id();
        glUseProgram(program);
        glProgramUniform2f(program, kFullResScaleLocation, scale.x, scale.y);
        glProgramUniform2f(program, kFragOffsetLocation, offset.x, offset.y);
        glProgramUniform1i(program, kFirstRankLocation, draw.ranks.first);
        glProgramUniform1i(program, kSeamPartLocation, draw.seamPart);
        gpu::applyPipeline(edges != nullptr ? *edges : drawState(draw.seamPart));
        glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, draw.ranks.count);
    }
}

}  // namespace nimbus::media
