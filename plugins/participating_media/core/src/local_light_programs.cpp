#include "local_light_programs.h"

#include "lamp_neighbourhood.h"

namespace nimbus::media {

LocalLightPrograms::LocalLightPrograms(gpu::ProgramDesc desc) : desc_(std::move(desc)), sunOnly_(gpu::compileProgram(desc_)) {}

const gpu::Program& LocalLightPrograms::forLights(const std::vector<assets::ResolvedLight>& lights) {
    if (!anyLamp(lights)) return sunOnly_;
    if (!localLights_) {
        gpu::ProgramDesc withLamps = desc_;
        withLamps.defines.push_back("MEDIA_LOCAL_LIGHTS");
        localLights_ = gpu::compileProgram(withLamps);
    }
    return localLights_;
}

}  // namespace nimbus::media
