// Fast particles: the billboards of `particles` mode in the same back-to-front order, with the
// source per vertex from the lighting pass and per fragment only the kernel's opacity from the
// pre-integrated table (shaders/media/particle_splats.*). Blends exactly as ParticlePass does.
// The particles a mesh lies inside (cut_lighting) are drawn in the same order with the exact
// tier's program (particles.* with PARTICLE_SPLAT_RUN).
#include "particles/particle_splat_pass.h"

#include "common/kernel_table.h"
#include "common/lit_media_inputs.h"
#include "common/frame_blocks.h"
#include "particles/particle_pass.h"
#include "nimbus/gpu/shader_program.h"
#include "nimbus/gpu/frame_layout.h"

namespace nimbus::media {

namespace {
constexpr GLint kFragmentSunLocation = 7;    // particle_light_layout.glsl uFragmentSun
constexpr GLint kFragmentLampsLocation = 8;  // particle_light_layout.glsl uFragmentLamps
constexpr GLint kFirstRankLocation = 12;     // particle_splats.vert uFirstRank
constexpr GLint kFragOffsetLocation = 13;    // particle_splats.frag and particles.frag uFragOffset
constexpr GLint kSoftParticlesLocation = 0;  // particles.frag uSoftParticles

bool sameVariant(const SplatRun& a, const SplatRun& b) {
    return a.meshCrossings == b.meshCrossings && a.lamps == b.lamps && a.depthTested == b.depthTested && a.meshInside == b.meshInside;
}

// Whether run a's variant draws b's particles as theirs would: the lamp bit never changes, the
// crossing variant takes a particle no mesh crosses, and the depth fetch takes any particle. The
// exact program would take any, but costs every fragment far more: it joins nothing.
bool covers(const SplatRun& a, const SplatRun& b) {
    return a.meshInside == b.meshInside && a.lamps == b.lamps && (a.meshCrossings || !b.meshCrossings) && (!a.depthTested || b.depthTested);
}

// One particle's run. A mesh inside it: its sphere reaches a box, so the depth test alone never clips it.
SplatRun runOf(std::uint32_t rank, std::uint8_t f) {
    const bool inside = (f & kSplatMeshInside) != 0;
    return {rank, 0, (f & kSplatNearMesh) != 0, (f & kSplatNearLamp) != 0, !inside && (f & kSplatClearOfMeshes) != 0, inside};
}

// `state` with its depth test's comparison `compare`.
gpu::PipelineState comparingDepth(gpu::PipelineState state, GLenum compare) {
    state.depth.compare = compare;
    return state;
}

// The scene depth as the target's depth attachment, read-only: where the host's depth is a depth
// texture of the target's size.
bool canDepthTest(const gpu::TextureDesc& depth, const MediaTarget& target) {
    return gpu::isDepthFormat(depth.format) && glm::ivec2(depth.width, depth.height) == target.size;
}

// The splats' state with the depth test: a splat's fragment only where its quad's depth lies in
// front of the scene's (reversed Z), writing none.
gpu::PipelineState depthTested(gpu::PipelineState state) {
    state.depth = {.test = true, .compare = GL_GEQUAL, .write = false};
    return state;
}
}  // namespace

ParticleSplatPass::ParticleSplatPass() : kernelTable_(createKernelTable()) {}

const gpu::Program& ParticleSplatPass::program(const SplatVariant& variant) {
    gpu::Program& p = programs_.at((variant.eyeInside ? 1 : 0) + (variant.lamps ? 2 : 0) + (variant.constant ? 4 : 0) +
                                (variant.meshCrossings ? 8 : 0) + (variant.multiple ? 16 : 0) + (variant.rankList ? 32 : 0) + (variant.depthTested ? 64 : 0) +
                                (variant.lamps && variant.pointLamps ? 128 : 0) + (variant.farDepth ? 256 : 0));
    if (!p) p = gpu::compileProgram(particleSplatDesc(variant));
    return p;
}

gpu::ProgramDesc particleSplatDesc(const SplatVariant& variant) {
    gpu::ProgramDesc desc{.vertex = "media/particles/particle_splats.vert", .fragment = "media/particles/particle_splats.frag"};
    if (variant.eyeInside) desc.defines.push_back("MEDIA_EYE_INSIDE");
    if (variant.lamps) desc.defines.push_back("MEDIA_FRAGMENT_LAMPS");
    if (variant.lamps && variant.pointLamps) desc.defines.push_back("MEDIA_POINT_LAMPS");
    if (variant.constant) desc.defines.push_back("SPLAT_CONSTANT");
    if (variant.meshCrossings && !variant.constant) desc.defines.push_back("MEDIA_MESH_CROSSINGS");
    if (variant.multiple) desc.defines.push_back("MEDIA_MULTIPLE");
    if (variant.rankList) desc.defines.push_back("SPLAT_RANK_LIST");
    if (variant.depthTested) desc.defines.push_back("SPLAT_DEPTH_TESTED");
    if (variant.farDepth) desc.defines.push_back("SPLAT_FAR_DEPTH");
    return desc;
}

gpu::ProgramDesc particleCutRunDesc(bool rankList) {
    gpu::ProgramDesc desc = particlesDesc(true);
    desc.defines.push_back("PARTICLE_SPLAT_RUN");
    if (rankList) desc.defines.push_back("SPLAT_RANK_LIST");
    return desc;
}

std::vector<SplatRun> splatRuns(const std::vector<std::uint32_t>& order, const std::vector<std::uint8_t>& flags, std::uint32_t minGap,
                                std::uint8_t mask) {
    std::vector<SplatRun> runs;
    const auto count = static_cast<std::uint32_t>(order.size());
    for (std::uint32_t rank = 0; rank < count; ++rank) {
        const SplatRun own = runOf(rank, flags[order[rank]] & mask);
        if (runs.empty() || !sameVariant(runs.back(), own)) runs.push_back(own);
        ++runs.back().count;
    }
    // Join a short run between two runs of one variant that covers it into one run.
    std::vector<SplatRun> joined;
    for (std::size_t i = 0; i < runs.size(); ++i) {
        const SplatRun& run = runs[i];
        const bool bridge = !joined.empty() && run.count < minGap && i + 1 < runs.size() && sameVariant(joined.back(), runs[i + 1]) &&
                            covers(joined.back(), run);
        if (!joined.empty() && (bridge || sameVariant(joined.back(), run)))
            joined.back().count += run.count;
        else
            joined.push_back(run);
    }
    return joined;
}

gpu::ResourceHandle ParticleSplatPass::add(gpu::FrameGraph& graph, GraphFrame& context, const ParticleGpuBuffer& buffer,
                                              const ParticleLightingPass& lighting, SplatVariant variant, std::vector<std::uint8_t> flags,
                                              const FragmentLamps& lamps, const MediaTarget& target) {
    const bool depthTest = canDepthTest(graph.desc(context.sceneDepth), target);
    const auto& data = graph.addPass<SplatInputs>(
        "media_particle_splats",
        [&](gpu::PassBuilder& builder, SplatInputs& d) {
            d.media = declareMediaTarget(builder, target);
            declareInputs(builder, context, variant, lamps, d);
        },
        [this, variant, flags = std::move(flags), &context, &buffer, &lighting, lamps, target, depthTest](
            const gpu::PassResources& resources, const SplatInputs& d) {
            const gpu::Framebuffer fbo = bindMediaTarget(resources.id(d.media), target);
            // Read-only (no depth writes), so the fetching variants may sample it while attached.
            if (depthTest) glNamedFramebufferTexture(fbo.id(), GL_DEPTH_ATTACHMENT, resources.id(d.depth), 0);
            draw(resources, d, {.context = context, .buffer = buffer, .lighting = lighting, .variant = variant, .flags = flags, .lamps = lamps},
                 target.fullResScale, depthTest ? depthTested(mediaOver(target)) : mediaOver(target));
        });
    return data.media;
}

void ParticleSplatPass::declareInputs(gpu::PassBuilder& builder, const GraphFrame& context, const SplatVariant& variant,
                                      const FragmentLamps& lamps, SplatInputs& d) {
    const bool anyLamps = lamps.lamps[0] >= 0;
    d.depth = builder.read(context.sceneDepth);
    if ((anyLamps || variant.meshInside) && context.slices.valid()) d.slices = builder.read(context.slices);
    if ((anyLamps || variant.meshCrossings || variant.meshInside) && context.shadowMap.valid()) d.shadowMap = builder.read(context.shadowMap);
}

void ParticleSplatPass::draw(const gpu::PassResources& resources, const SplatInputs& d, const SplatDraw& s, glm::vec2 scale,
                             const gpu::PipelineState& state, glm::vec2 offset, const std::vector<std::uint32_t>& ranks) {
    SplatVariant variant = s.variant;
    variant.multiple = s.context.multiple;
    variant.rankList = !ranks.empty();
    variant.pointLamps = s.lamps.allPoint;
    // The particle at each place of the draw: its rank's, or its listed rank's.
    std::vector<std::uint32_t> listed;
    if (variant.rankList) {
        const std::size_t bytes = ranks.size() * sizeof(std::uint32_t);
        if (bytes > ranksCapacity_) {
            ranksCapacity_ = std::max(bytes, 2 * ranksCapacity_);
            ranks_ = gpu::createBuffer(ranksCapacity_);
        }
        glNamedBufferSubData(ranks_.id(), 0, static_cast<GLsizeiptr>(bytes), ranks.data());
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kSplatRanksBinding, ranks_.id());
        listed.reserve(ranks.size());
        for (const std::uint32_t rank : ranks) listed.push_back(s.buffer.order()[rank]);
    }
    s.context.blocks->bind();
    s.buffer.bindParticles();
    s.buffer.bindOrder();
    // The lamps' neighbour order (splat_source.glsl, and the exact program's lighting.glsl).
    if (s.lamps.lamps[0] >= 0 || variant.meshInside) s.buffer.bindLampNeighbourhoods();
    s.lighting.bind();
    glBindTextureUnit(kSceneDepthUnit, resources.id(d.depth));
    glBindTextureUnit(kKernelTableUnit, kernelTable_.id());
    if (d.slices.valid()) glBindTextureUnit(kSlicesUnit, resources.id(d.slices));
    if (d.shadowMap.valid()) glBindTextureUnit(kShadowDepthUnit, resources.id(d.shadowMap));
    gpu::applyPipeline(state);
    glBindVertexArray(vertexArray_.id());
    // The order is known only now: the upload pass sorted it.
    // Without the depth test every run fetches the depth.
    const std::uint8_t mask = state.depth.test ? 0xFF : static_cast<std::uint8_t>(~kSplatClearOfMeshes);
    for (const SplatRun& run : splatRuns(variant.rankList ? listed : s.buffer.order(), s.flags, 8, mask)) {
        SplatVariant own = variant;
        own.meshCrossings = run.meshCrossings;
        own.lamps = run.lamps;
        own.depthTested = run.depthTested;
        if (!run.meshInside) {
            drawRun(s, own, run, scale, offset);
        } else if (!state.depth.test || !variant.cutRays) {
            // Its quad at the far side: no depth test (a particle a surface hides discards early).
            if (state.depth.test) gpu::applyPipeline(comparingDepth(state, GL_ALWAYS));
            drawCutRun(s, run, variant.rankList, scale, offset);
            if (state.depth.test) gpu::applyPipeline(state);
        } else {
            // The exact program costs every fragment it draws: the fit where every surface lies
            // behind the sphere, the exact program where one lies in front of its far side.
            own.farDepth = true;
            gpu::applyPipeline(comparingDepth(state, GL_GREATER));
            drawRun(s, own, run, scale, offset);
            gpu::applyPipeline(comparingDepth(state, GL_LEQUAL));
            drawCutRun(s, run, variant.rankList, scale, offset);
            gpu::applyPipeline(state);
        }
    }
}

void ParticleSplatPass::drawRun(const SplatDraw& s, const SplatVariant& variant, const SplatRun& run, glm::vec2 scale, glm::vec2 offset) {
    const GLuint id = program(variant).id();
    glUseProgram(id);
    glProgramUniform2f(id, 1, scale.x, scale.y);
    glProgramUniform2f(id, kFragOffsetLocation, offset.x, offset.y);
    glProgramUniform1i(id, kFragmentSunLocation, s.lamps.sun);
    if (run.lamps) glProgramUniform1iv(id, kFragmentLampsLocation, kMaxFragmentLamps, s.lamps.lamps.data());
    glProgramUniform1i(id, kFirstRankLocation, static_cast<GLint>(run.first));
    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(run.count));
}

void ParticleSplatPass::drawCutRun(const SplatDraw& s, const SplatRun& run, bool rankList, glm::vec2 scale, glm::vec2 offset) {
    std::unique_ptr<LocalLightPrograms>& programs = cutPrograms_.at(rankList ? 1 : 0);
    if (!programs) programs = std::make_unique<LocalLightPrograms>(particleCutRunDesc(rankList));
    const GLuint id = programs->forLights(s.context.host.lights, s.context.multiple).id();
    glUseProgram(id);
    glProgramUniform1i(id, kSoftParticlesLocation, 1);
    glProgramUniform2f(id, 1, scale.x, scale.y);
    glProgramUniform2f(id, kFragOffsetLocation, offset.x, offset.y);
    glProgramUniform1i(id, kFirstRankLocation, static_cast<GLint>(run.first));
    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(run.count));
}

}  // namespace nimbus::media
