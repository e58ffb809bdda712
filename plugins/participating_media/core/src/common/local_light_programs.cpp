#include "common/local_light_programs.h"

#include "common/lamp_neighbourhood.h"

namespace nimbus::media {

LocalLightPrograms::LocalLightPrograms(gpu::ProgramDesc desc) : desc_(std::move(desc)) { builds_[0] = gpu::compileProgram(desc_); }

const gpu::Program& LocalLightPrograms::forLights(const std::vector<Light>& lights, bool multiple) {
    const bool lamps = anyLamp(lights);
    gpu::Program& build = builds_[(lamps ? 1 : 0) + (multiple ? 2 : 0)];
    if (!build) {
        gpu::ProgramDesc desc = lamps ? withLocalLights(desc_) : desc_;
        if (multiple) desc.defines.push_back("MEDIA_MULTIPLE");
        build = gpu::compileProgram(desc);
    }
    return build;
}

gpu::ProgramDesc LocalLightPrograms::withLocalLights(gpu::ProgramDesc desc) {
    desc.defines.push_back("MEDIA_LOCAL_LIGHTS");
    return desc;
}

}  // namespace nimbus::media
