// Per-particle lighting (fast and balanced tiers): one compute invocation per particle, in draw
// order, evaluates its source at nine rays through its billboard (shaders/media/particles/particle_lighting.comp)
// into a buffer the splats read per vertex. Fragments then pay for opacity only.
#include <algorithm>

#include "particles/particle_lighting_pass.h"

#include "common/frame_blocks.h"
#include "nimbus/gpu/shader_program.h"
#include "nimbus/gpu/frame_layout.h"

namespace nimbus::media {

namespace {
constexpr GLuint kLocalSize = 64;
constexpr GLint kFragmentSunLocation = 7;    // particle_light_layout.glsl uFragmentSun
constexpr GLint kFragmentLampsLocation = 8;  // particle_light_layout.glsl uFragmentLamps
constexpr std::size_t kSlotsPerParticle = 8, kSlotsPerConstantParticle = 2;  // particle_light_layout.glsl
}  // namespace

ParticleLightingPass::ParticleLightingPass() = default;

const gpu::Program& ParticleLightingPass::program(const GraphFrame& context, const LightingVariant& variant) {
    std::unique_ptr<LocalLightPrograms>& p =
        programs_[(variant.exact ? 1 : 0) + (variant.constant ? 2 : 0) + (variant.meshCrossings ? 4 : 0) + (variant.lampRuns ? 8 : 0)];
    if (!p) p = std::make_unique<LocalLightPrograms>(particleLightingDesc(variant));
    return p->forLights(context.host.lights, context.multiple);
}

gpu::ProgramDesc particleLightingDesc(const LightingVariant& variant) {
    gpu::ProgramDesc desc{.compute = "media/particles/particle_lighting.comp"};
    if (variant.exact) desc.defines = {"LIGHTING_EXACT", "MEDIA_LAYER_LIGHT"};
    if (variant.constant) desc.defines.push_back("SPLAT_CONSTANT");
    if (variant.meshCrossings) desc.defines.push_back("MEDIA_MESH_CROSSINGS");
    if (variant.meshCrossings || variant.lampRuns) desc.defines.push_back("MEDIA_SPLAT_FLAGS");
    return desc;
}

void ParticleLightingPass::add(gpu::FrameGraph& graph, GraphFrame& context, const ParticleGpuBuffer& buffer,
                               std::size_t particles, const LightingVariant& variant, const FragmentLamps& lamps,
                               const std::vector<std::uint8_t>& flags) {
    const gpu::Program& program = this->program(context, variant);
    // Sized from the set: the buffer fills when the upload pass runs.
    const std::size_t bytes = std::max<std::size_t>(particles, 1) * (variant.constant ? kSlotsPerConstantParticle : kSlotsPerParticle) * sizeof(glm::vec4);
    if (!light_ || capacity_ < bytes) {
        capacity_ = std::max(bytes, capacity_ * 3 / 2);
        light_ = gpu::createBuffer(capacity_, nullptr, 0);
    }
    const bool withFlags = variant.meshCrossings || variant.lampRuns;
    if (withFlags) {
        flagsStaging_.assign(flags.begin(), flags.end());
        flagsStaging_.resize(std::max<std::size_t>(particles, 1), 0u);
        const std::size_t flagBytes = flagsStaging_.size() * sizeof(std::uint32_t);
        if (!flags_ || flagsCapacity_ < flagBytes) {
            flagsCapacity_ = std::max(flagBytes, flagsCapacity_ * 3 / 2);
            flags_ = gpu::createBuffer(flagsCapacity_, nullptr, GL_DYNAMIC_STORAGE_BIT);
        }
        glNamedBufferSubData(flags_.id(), 0, static_cast<GLsizeiptr>(flagBytes), flagsStaging_.data());
    }
    struct Data {
        gpu::ResourceHandle shadowMap, slices;
    };
    graph.addPass<Data>(
        "media_particle_lighting",
        [&](gpu::PassBuilder& builder, Data& d) {
            if (context.shadowMap.valid()) d.shadowMap = builder.read(context.shadowMap);
            if (context.slices.valid()) d.slices = builder.read(context.slices);
            builder.sideEffect();  // fills this pass's own buffer, which the splats read
        },
        [this, &program, &context, &buffer, lamps, withFlags](const gpu::PassResources& resources, const Data& d) {
            const auto count = static_cast<GLuint>(buffer.count());
            glUseProgram(program.id());
            context.blocks->bind();
            buffer.bindParticles();
            buffer.bindOrder();
            buffer.bindLampNeighbourhoods();
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kParticleLightBinding, light_.id());
            if (withFlags) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kSplatFlagsBinding, flags_.id());
            if (d.shadowMap.valid()) glBindTextureUnit(kShadowDepthUnit, resources.id(d.shadowMap));
            if (d.slices.valid()) glBindTextureUnit(kSlicesUnit, resources.id(d.slices));
            glProgramUniform1ui(program.id(), 0, count);
            glProgramUniform1i(program.id(), kFragmentSunLocation, lamps.sun);
            glProgramUniform1iv(program.id(), kFragmentLampsLocation, kMaxFragmentLamps, lamps.lamps.data());
            glDispatchCompute((count + kLocalSize - 1) / kLocalSize, 1, 1);
            glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
        });
}

FragmentLamps fragmentLamps(const std::vector<Light>& lights) {
    FragmentLamps out;
    out.lamps.fill(-1);
    std::size_t k = 0;
    out.allPoint = true;
    for (std::size_t i = 0; i < lights.size(); ++i) {
        if (lights[i].kind == gpu::LightKind::Directional) {
            if (out.sun < 0) out.sun = static_cast<GLint>(i);
        } else if (k < out.lamps.size()) {
            out.lamps[k++] = static_cast<GLint>(i);
            out.allPoint = out.allPoint && lights[i].kind == gpu::LightKind::Point;
        }
    }
    out.allPoint = out.allPoint && k > 0;
    return out;
}

void ParticleLightingPass::bind() const { glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kParticleLightBinding, light_.id()); }

}  // namespace nimbus::media
