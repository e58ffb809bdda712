#pragma once
// The `particle_lighting` pass: per-particle lighting of the fast tiers (shaders/media/particles/particle_lighting.comp).
#include <array>
#include <memory>
#include <vector>

#include "common/local_light_programs.h"
#include "common/particle_buffer.h"
#include "nimbus/gpu/frame_graph.h"
#include "nimbus/gpu/gl_objects.h"
#include "nimbus/gpu/shader_program.h"
#include "nimbus/media/graph_frame.h"

namespace nimbus::media {

inline constexpr int kMaxFragmentLamps = 2;  // shaders/media/common/particle_light_layout.glsl MAX_FRAGMENT_LAMPS

// The lights the fast splats evaluate per fragment (−1: none): the first directional light's phase
// function (g = 0.99 peaks within a few pixels), and point and spot lights' 1/d² (near a lamp it
// peaks across a particle far more sharply than any fit follows).
struct FragmentLamps {
    GLint sun = -1;
    std::array<GLint, kMaxFragmentLamps> lamps{};
    bool allPoint = false;  // every listed lamp is a point light (six views): MEDIA_POINT_LAMPS
};
FragmentLamps fragmentLamps(const std::vector<Light>& lights);

// Per particle, the splat variant that draws it (particle_lighting.comp SplatFlags): near a mesh
// (the mesh-crossing variant), near a fragment lamp (MEDIA_FRAGMENT_LAMPS; the fit takes the lamps
// of the others), clear of meshes (particlesClearOfMeshes: the depth test clips it, with no
// scene-depth fetch; only the splat pass reads this bit), a mesh inside it (the splat pass shades
// it per fragment as the exact tier does, whatever its other bits; the lighting pass ignores it).
enum SplatFlag : std::uint8_t { kSplatNearMesh = 1, kSplatNearLamp = 2, kSplatClearOfMeshes = 4, kSplatMeshInside = 8 };

// Per-particle lighting (the fast tiers): each particle's source fitted over its billboard, in draw
// order, from nine rays through it.
struct LightingVariant {
    bool exact = false;          // each ray shaded as particles.frag shades a pixel
    bool constant = false;       // the centre ray alone, for particles a few pixels wide
    bool meshCrossings = false;  // flag the particles a mesh crosses, for the splats' MEDIA_MESH_CROSSINGS
    bool lampRuns = false;       // the fragment lamps only on particles flagged kSplatNearLamp (else on all)
};
// The per-particle lighting program (particle_lighting.comp).
gpu::ProgramDesc particleLightingDesc(const LightingVariant& variant);

class ParticleLightingPass {
public:
    ParticleLightingPass();
    // `flags` (per particle, SplatFlag bits): with variant.meshCrossings the particles it may flag as
    // crossed, with variant.lampRuns those whose fragments evaluate the lamps.
    void add(gpu::FrameGraph& graph, GraphFrame& context, const ParticleGpuBuffer& buffer, std::size_t particles,
             const LightingVariant& variant, const FragmentLamps& lamps, const std::vector<std::uint8_t>& flags = {});
    void bind() const;  // the lighting buffer, for the splats

private:
    const gpu::Program& program(const GraphFrame& context, const LightingVariant& variant);
    std::unique_ptr<LocalLightPrograms> programs_[16];  // by exact + 2·constant + 4·meshCrossings + 8·lampRuns, built when first asked for
    gpu::Buffer light_, flags_;
    std::size_t capacity_ = 0, flagsCapacity_ = 0;
    std::vector<std::uint32_t> flagsStaging_;
};

}  // namespace nimbus::media
