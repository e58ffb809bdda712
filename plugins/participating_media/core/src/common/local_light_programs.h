#pragma once
// Two builds of one media shader: with MEDIA_LOCAL_LIGHTS (point and spot lights integrated along
// each composited segment, shaders/media/common/local_light_segment.glsl) and without, for frames lit by
// directional lights only. llvmpipe runs both sides of a branch under masks, so the lamp code costs
// a sunlit frame even where no lamp exists (docs/design-notes.md).
//
// Does not: decide per light or per pixel (one frame, one build), or compile the lamp build before a
// frame first needs it.
#include <vector>

#include "nimbus/media/host.h"
#include "nimbus/gpu/shader_program.h"

namespace nimbus::media {

class LocalLightPrograms {
public:
    explicit LocalLightPrograms(gpu::ProgramDesc desc);
    // The build for a frame lit by `lights`.
    const gpu::Program& forLights(const std::vector<Light>& lights);
    // `desc` as the lamp build compiles it.
    static gpu::ProgramDesc withLocalLights(gpu::ProgramDesc desc);

private:
    gpu::ProgramDesc desc_;
    gpu::Program sunOnly_;
    gpu::Program localLights_;
};

}  // namespace nimbus::media
