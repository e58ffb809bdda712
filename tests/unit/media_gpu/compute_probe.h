#pragma once
// A GLSL probe (tests/unit/media_gpu/shaders/*.comp, local size 64) run over `count` items: its
// input buffer at storage binding 0, its outputs read back from binding 1. The probes put the
// GLSL of the renderer beside the C++ it must match.
#include <filesystem>
#include <functional>
#include <vector>

#include "nimbus/gpu/gl_objects.h"
#include "nimbus/gpu/shader_program.h"

namespace nimbus::media::test {

// `setUniforms` sets the probe's own uniforms (its item count among them) on its program.
template <typename Out, typename In>
std::vector<Out> runComputeProbe(const char* shader, const std::vector<In>& input, std::size_t count,
                                 const std::function<void(GLuint)>& setUniforms) {
    const gpu::Program program = gpu::compileProgram({.compute = shader, .folder = std::filesystem::path(NIMBUS_MEDIA_GPU_TEST_SHADERS)});
    const gpu::Buffer in = gpu::createBuffer(input.size() * sizeof(In), input.data(), 0);
    const gpu::Buffer out = gpu::createBuffer(count * sizeof(Out), nullptr, GL_DYNAMIC_STORAGE_BIT | GL_MAP_READ_BIT);
    glUseProgram(program.id());
    setUniforms(program.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, in.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, out.id());
    glDispatchCompute(static_cast<GLuint>((count + 63) / 64), 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<Out> values(count);
    glGetNamedBufferSubData(out.id(), 0, static_cast<GLsizeiptr>(values.size() * sizeof(Out)), values.data());
    return values;
}

}  // namespace nimbus::media::test
