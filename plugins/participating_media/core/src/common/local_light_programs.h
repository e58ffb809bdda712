#pragma once
// The builds of one media shader a frame may need: with MEDIA_LOCAL_LIGHTS (point and spot lights
// integrated along each composited segment, shaders/media/common/local_light_segment.glsl) or not,
// for frames lit by directional lights only; and with MEDIA_MULTIPLE (the multiple-scattering
// model's grid, shaders/media/common/multiple_scattering.glsl) or not. llvmpipe
// runs both sides of a branch under masks, so the lamp code costs a sunlit frame even where no lamp
// exists (docs/design-notes.md), and a single-scattering frame keeps today's build bit for bit.
//
// Does not: decide per light or per pixel (one frame, one build), or compile a build before a
// frame first needs it.
#include <array>
#include <vector>

#include "nimbus/media/host.h"
#include "nimbus/gpu/shader_program.h"

namespace nimbus::media {

class LocalLightPrograms {
public:
    explicit LocalLightPrograms(gpu::ProgramDesc desc);
    // The build for a frame lit by `lights`, in the multiple-scattering model or not.
    const gpu::Program& forLights(const std::vector<Light>& lights, bool multiple);
    // `desc` as the lamp build compiles it.
    static gpu::ProgramDesc withLocalLights(gpu::ProgramDesc desc);

private:
    gpu::ProgramDesc desc_;
    std::array<gpu::Program, 4> builds_;  // by lamps + 2·multiple
};

}  // namespace nimbus::media
