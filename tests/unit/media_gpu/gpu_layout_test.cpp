// The C++ mirrors of the media shaders' storage blocks (particle_buffer.h GpuParticle,
// block_passes.h GpuBlockTile) and their binding points, against the layout the driver gives
// shaders/media/particle_data.glsl and block_data.glsl in the programs that read them.
#include <cstddef>

#include "../gpu/gl_test_context.h"
#include "../gpu/glsl_layout.h"
#include "block_passes.h"
#include "media_passes.h"
#include "nimbus/gpu/shader_program.h"
#include "particle_buffer.h"

namespace nimbus::media {
namespace {

using gpu::test::expectMembers;
using gpu::test::topLevelArrayStride;

class MediaGpuLayout : public gpu::test::GlTest {};

GLint storageBinding(GLuint program, const char* block) {
    return gpu::test::resourceProperty(program, GL_SHADER_STORAGE_BLOCK, block, GL_BUFFER_BINDING);
}

TEST_F(MediaGpuLayout, ParticlesMatchGpuParticle) {
    const gpu::Program program = gpu::compileProgram({.vertex = "media/particles.vert", .fragment = "media/particles.frag"});
    expectMembers(program.id(), GL_BUFFER_VARIABLE, "particles[0].",
                  {{"positionRadius", offsetof(GpuParticle, positionRadius)},
                   {"albedoSigma", offsetof(GpuParticle, albedoSigma)},
                   {"emissionG", offsetof(GpuParticle, emissionG)},
                   {"extra", offsetof(GpuParticle, extra)}});
    EXPECT_EQ(topLevelArrayStride(program.id(), "particles[0].positionRadius"), static_cast<GLint>(sizeof(GpuParticle)));
    EXPECT_EQ(storageBinding(program.id(), "Particles"), static_cast<GLint>(kParticlesBinding));
    EXPECT_EQ(storageBinding(program.id(), "DrawOrder"), static_cast<GLint>(kDrawOrderBinding));
}

TEST_F(MediaGpuLayout, BlockTilesMatchGpuBlockTile) {
    const gpu::Program program =
        gpu::compileProgram({.vertex = "media/block_composite.vert", .fragment = "media/block_composite.frag"});
    expectMembers(program.id(), GL_BUFFER_VARIABLE, "blockTiles[0].",
                  {{"rect", offsetof(GpuBlockTile, rect)},
                   {"atlas", offsetof(GpuBlockTile, atlas)},
                   {"centreRadius", offsetof(GpuBlockTile, centreRadius)},
                   {"instance", offsetof(GpuBlockTile, instance)},
                   {"lampSlices", offsetof(GpuBlockTile, lampSlices)}});
    EXPECT_EQ(topLevelArrayStride(program.id(), "blockTiles[0].rect"), static_cast<GLint>(sizeof(GpuBlockTile)));
    EXPECT_EQ(storageBinding(program.id(), "BlockTiles"), static_cast<GLint>(kBlockTilesBinding));
}

TEST_F(MediaGpuLayout, ParticleLightIsReadWhereTheLightingPassWritesIt) {
    const gpu::Program lighting = gpu::compileProgram({.compute = "media/particle_lighting.comp"});
    const gpu::Program splats = gpu::compileProgram({.vertex = "media/particle_splats.vert", .fragment = "media/particle_splats.frag"});
    EXPECT_EQ(storageBinding(lighting.id(), "ParticleLight"), static_cast<GLint>(kParticleLightBinding));
    EXPECT_EQ(storageBinding(splats.id(), "ParticleLight"), static_cast<GLint>(kParticleLightBinding));
    EXPECT_EQ(storageBinding(lighting.id(), "Particles"), static_cast<GLint>(kParticlesBinding));
}

}  // namespace
}  // namespace nimbus::media
