#pragma once
// The `media_sheets` pass of `sheets` mode (shaders/media/sheets/sheet_splats.*, sheet_composite.frag).
#include <array>
#include <memory>

#include "common/local_light_programs.h"
#include "common/media_target.h"
#include "common/particle_buffer.h"
#include "nimbus/gpu/frame_graph.h"
#include "nimbus/gpu/gl_objects.h"
#include "nimbus/gpu/shader_program.h"
#include "nimbus/media/graph_frame.h"
#include "particles/particle_lighting_pass.h"
#include "sheets/sheet_plan.h"

namespace nimbus::media {

// The sheet splat program: lamps per fragment (all of them point lights: pointLamps), one ray per
// particle (as particleSplatDesc).
gpu::ProgramDesc sheetSplatDesc(bool lamps, bool constant, bool multiple = false, bool pointLamps = false);
// The exact tier's slab program (sheet_exact.*), lit per fragment; LocalLightPrograms adds its builds.
gpu::ProgramDesc sheetExactDesc();
gpu::ProgramDesc sheetCompositeDesc();

// Image-aligned sheet-buffer splatting (Mueller and Crawfis; the sheet-buffer splatting paper): for
// each sheet, back to front, every particle's pre-integrated slab in it is added into a sheet
// buffer (rgb Σ τ_i J_i, a Σ τ_i), which is then composited over the media target as one layer.
// The slabs carry the per-particle lighting pass's source (`lighting`, in the view-depth order),
// or with `lighting` null are lit per fragment over each slab, as particles.frag lights a pixel.
// The sheet buffer is this pass's own: it lives only between a sheet's splats and its composite.
class SheetPass {
public:
    SheetPass();
    gpu::ResourceHandle add(gpu::FrameGraph& graph, GraphFrame& context, const ParticleGpuBuffer& buffer,
                            const ParticleLightingPass* lighting, const SheetPlan& plan, bool constant, const FragmentLamps& lamps,
                            const MediaTarget& target);

private:
    const gpu::Program& splatProgram(bool lamps, bool constant, bool multiple, bool pointLamps);
    std::array<gpu::Program, 16> splatPrograms_;  // by lamps + 2·constant + 4·multiple + 8·pointLamps, built when first asked for
    std::unique_ptr<LocalLightPrograms> exact_;  // built when first asked for
    gpu::Program composite_;
    gpu::Texture kernelTable_;
    gpu::VertexArray vertexArray_ = gpu::createVertexArray();
};

}  // namespace nimbus::media
