#pragma once
// The `particle_splats` pass of the fast tiers (shaders/media/particle_splats.*).
#include <array>

#include "common/particle_buffer.h"
#include "common/media_target.h"
#include "nimbus/gpu/frame_graph.h"
#include "nimbus/gpu/gl_objects.h"
#include "nimbus/gpu/pipeline_state.h"
#include "nimbus/gpu/shader_program.h"
#include "nimbus/media/graph_frame.h"
#include "particles/particle_lighting_pass.h"

namespace nimbus::media {

// Fast particles: the sorted billboards with per-vertex source and per-fragment opacity from the
// pre-integrated kernel table.
struct SplatVariant {
    bool eyeInside = false;      // some particle contains the eye (its segment starts there)
    bool lamps = false;          // point or spot lights per fragment (set by add from its lamps)
    bool pointLamps = false;     // with lamps: all of them point lights (set by draw from its lamps)
    bool constant = false;       // one ray per particle (LightingVariant::constant)
    bool meshCrossings = false;  // the sun's mesh visibility per fragment where the lighting pass flags a crossing
    bool multiple = false;       // the multiple model: the sun's forward-peak orders (set by add from the frame)
    bool rankList = false;       // draws the ranks a list holds (set by draw when given one)
    // Clipped by the depth test alone, its quad through the centre, with no scene-depth fetch (set
    // by draw for a run clear of meshes). The others' quads sit at their sphere's nearest depth, so
    // the test only drops what a surface hides whole, and their fragments fetch the depth.
    bool depthTested = false;
    // Some particle has a mesh inside it (kSplatMeshInside, in the flags given with it): its runs
    // take the exact tier's per-fragment program, which reads the slices and the shadow map.
    bool meshInside = false;
    // With meshInside: the exact program only on the rays a surface may cut inside the sphere (in
    // front of its far side), where the pass tests depth; this program's fit on the others.
    bool cutRays = false;
    // The quad at its sphere's farthest depth (set by draw for such a run's fit).
    bool farDepth = false;
};
// The splat program (particle_splats.*).
gpu::ProgramDesc particleSplatDesc(const SplatVariant& variant);

// The program of a run of the particles a mesh lies inside: the exact tier's (particles.*), with
// the splats' runs, rank list and target offset.
gpu::ProgramDesc particleCutRunDesc(bool rankList);

// A run of consecutive draw ranks drawn with one program: with the mesh-crossing variant or not,
// with the fragment lamps or not, clipped by the depth test alone or not. With meshInside the exact
// tier's program (with SplatVariant::cutRays only where a surface lies in front of a sphere's far
// side, its own variant elsewhere; depthTested then false).
struct SplatRun {
    std::uint32_t first = 0, count = 0;
    bool meshCrossings = false;
    bool lamps = false;
    bool depthTested = false;
    bool meshInside = false;
};
// The runs of `order` (particle index per rank) by `flags` (per particle, SplatFlag bits): a
// variant costs every fragment it draws, flagged or not (llvmpipe), so only the flagged ranks take
// it. A gap of fewer than `minGap` ranks between two runs of one variant that can draw it (the
// crossing variant, or the depth fetch) joins them (a draw call each costs more); the lamp bit
// never joins, as the lighting pass put the lamps of the particles without it in their fit.
// Flags are read through `mask`.
std::vector<SplatRun> splatRuns(const std::vector<std::uint32_t>& order, const std::vector<std::uint8_t>& flags,
                                std::uint32_t minGap = 8, std::uint8_t mask = 0xFF);

class ParticleSplatPass {
public:
    ParticleSplatPass();
    // `flags` (one per particle, SplatFlag bits, as the lighting pass had them): the variant each
    // particle is drawn with, in runs of the draw order (splatRuns) found when the pass runs, after
    // the sort. A mesh bit only with variant.meshCrossings, a lamp bit only with fragment lamps;
    // each variant's program is built when a run first asks for it.
    gpu::ResourceHandle add(gpu::FrameGraph& graph, GraphFrame& context, const ParticleGpuBuffer& buffer,
                               const ParticleLightingPass& lighting, SplatVariant variant, std::vector<std::uint8_t> flags,
                               const FragmentLamps& lamps, const MediaTarget& target);

    // What one draw of the splats needs besides its target (the main pass's and the edges').
    struct SplatInputs {
        gpu::ResourceHandle media, depth, slices, shadowMap;
    };
    struct SplatDraw {
        GraphFrame& context;
        const ParticleGpuBuffer& buffer;
        const ParticleLightingPass& lighting;
        SplatVariant variant;
        const std::vector<std::uint8_t>& flags;
        const FragmentLamps& lamps;
    };
    static void declareInputs(gpu::PassBuilder& builder, const GraphFrame& context, const SplatVariant& variant, const FragmentLamps& lamps,
                              SplatInputs& d);
    // Every particle, or only the draw ranks `ranks` lists (in order) where it is not empty, into
    // the bound framebuffer under `state`: its pixel p is the viewport's p · scale + offset.
    void draw(const gpu::PassResources& resources, const SplatInputs& d, const SplatDraw& s, glm::vec2 scale,
              const gpu::PipelineState& state, glm::vec2 offset = glm::vec2(0.0f), const std::vector<std::uint32_t>& ranks = {});

private:
    const gpu::Program& program(const SplatVariant& variant);
    // A run with the splat program `variant`, or with the exact tier's (a run of particles a mesh lies inside).
    void drawRun(const SplatDraw& s, const SplatVariant& variant, const SplatRun& run, glm::vec2 scale, glm::vec2 offset);
    void drawCutRun(const SplatDraw& s, const SplatRun& run, bool rankList, glm::vec2 scale, glm::vec2 offset);
    // By eyeInside + 2·lamps + 4·constant + 8·meshCrossings + 16·multiple + 32·rankList + 64·depthTested
    // + 128·pointLamps (with lamps) + 256·farDepth, built when first asked for.
    std::array<gpu::Program, 512> programs_;
    std::array<std::unique_ptr<LocalLightPrograms>, 2> cutPrograms_;  // particleCutRunDesc by rankList
    gpu::Buffer ranks_;          // draw's `ranks`, grown as needed
    std::size_t ranksCapacity_ = 0;
    gpu::Texture kernelTable_;
    gpu::VertexArray vertexArray_ = gpu::createVertexArray();
};

}  // namespace nimbus::media
