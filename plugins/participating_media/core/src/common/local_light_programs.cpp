#include "common/local_light_programs.h"

#include "common/lamp_neighbourhood.h"

namespace nimbus::media {

LocalLightPrograms::LocalLightPrograms(gpu::ProgramDesc desc) : desc_(std::move(desc)), sunOnly_(gpu::compileProgram(desc_)) {}

const gpu::Program& LocalLightPrograms::forLights(const std::vector<Light>& lights) {
    if (!anyLamp(lights)) return sunOnly_;
    if (!localLights_) localLights_ = gpu::compileProgram(withLocalLights(desc_));
    return localLights_;
}

gpu::ProgramDesc LocalLightPrograms::withLocalLights(gpu::ProgramDesc desc) {
    desc.defines.push_back("MEDIA_LOCAL_LIGHTS");
    return desc;
}

}  // namespace nimbus::media
