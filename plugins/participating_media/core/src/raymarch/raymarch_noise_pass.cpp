#include "raymarch/raymarch_noise_pass.h"

#include <algorithm>

#include <glm/gtc/type_ptr.hpp>

#include "nimbus/media/gpu_bindings.h"

namespace nimbus::media {

RaymarchNoisePass::RaymarchNoisePass() : program_(gpu::compileProgram({.compute = "media/raymarch/raymarch_noise.comp"})) {}

void RaymarchNoisePass::add(gpu::FrameGraph& graph, const RaymarchGrid& grid, const VoxelGrid& cpu, const std::vector<Volume>& volumes,
                            const VolumeGpuBuffer& buffer, const glm::dvec3& origin) {
    // Each noise volume's voxel range, found now (the CPU grid is this frame's).
    struct Range {
        int volume;
        glm::ivec3 first, last;
    };
    std::vector<Range> ranges;
    for (std::size_t v = 0; v < volumes.size(); ++v) {
        if (!volumes[v].noise) continue;
        const Aabb box = volumeBounds(volumes[v]);
        const glm::ivec3 first = glm::max(glm::ivec3(glm::floor((box.min - cpu.min) / cpu.voxel)), glm::ivec3(0));
        const glm::ivec3 last = glm::min(glm::ivec3(glm::floor((box.max - cpu.min) / cpu.voxel)), cpu.size - 1);
        if (glm::all(glm::lessThanEqual(first, last))) ranges.push_back({static_cast<int>(v), first, last});
    }
    struct Data {};
    graph.addPass<Data>(
        "raymarch_noise", [](gpu::PassBuilder& builder, Data&) { builder.sideEffect(); },
        [this, &grid, &buffer, ranges, corner = glm::vec3(cpu.min - origin), voxel = static_cast<float>(cpu.voxel.x)](const gpu::PassResources&,
                                                                                                                    const Data&) {
            const GLuint program = program_.id();
            glUseProgram(program);
            buffer.bind();
            glBindImageTexture(kGridScatteringImage, grid.scattering().id(), 0, GL_TRUE, 0, GL_READ_WRITE, GL_RGBA32F);
            glBindImageTexture(kGridEmissionImage, grid.emission().id(), 0, GL_TRUE, 0, GL_READ_WRITE, GL_RGBA32F);
            glBindImageTexture(kNoiseGridImage, grid.noise().id(), 0, GL_TRUE, 0, GL_READ_WRITE, GL_R32F);
            glProgramUniform3fv(program, 0, 1, glm::value_ptr(corner));
            glProgramUniform1f(program, 1, voxel);
            for (const Range& r : ranges) {
                glProgramUniform3iv(program, 2, 1, glm::value_ptr(r.first));
                glProgramUniform3iv(program, 3, 1, glm::value_ptr(r.last));
                glProgramUniform1i(program, 4, r.volume);
                const glm::ivec3 count = r.last - r.first + 1;
                glDispatchCompute(static_cast<GLuint>((count.x + 3) / 4), static_cast<GLuint>((count.y + 3) / 4), static_cast<GLuint>((count.z + 3) / 4));
                // The next volume reads what this one wrote.
                glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
            }
            // The raymarch and the volume slices sample what was written.
            glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
        });
}

}  // namespace nimbus::media
