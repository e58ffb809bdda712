// The C++ mirrors of the media shaders' blocks (particle_buffer.h GpuParticle, block_gpu_buffers.h
// GpuBlockTile, gpu_bindings.h GpuSliceViews) and every binding point of gpu_bindings.h, against
// the layout and bindings the driver gives the programs that read them.
#include <cstddef>

#include "gpu/gl_test_context.h"
#include "gpu/glsl_layout.h"
#include "blocks/block_composite_pass.h"
#include "blocks/block_impostor_lighting_pass.h"
#include "common/local_light_programs.h"
#include "particles/particle_lighting_pass.h"
#include "particles/particle_pass.h"
#include "particles/particle_splat_pass.h"
#include "sheets/sheet_pass.h"
#include "nimbus/gpu/shader_program.h"
#include "nimbus/media/gpu_bindings.h"
#include "common/particle_buffer.h"

namespace nimbus::media {
namespace {

using gpu::test::expectMembers;
using gpu::test::topLevelArrayStride;

class MediaGpuLayout : public gpu::test::GlTest {};

GLint storageBinding(GLuint program, const char* block) {
    return gpu::test::resourceProperty(program, GL_SHADER_STORAGE_BLOCK, block, GL_BUFFER_BINDING);
}

TEST_F(MediaGpuLayout, ParticlesMatchGpuParticle) {
    const gpu::Program program = gpu::compileProgram({.vertex = "media/particles/particles.vert", .fragment = "media/particles/particles.frag"});
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
        gpu::compileProgram({.vertex = "media/blocks/block_composite.vert", .fragment = "media/blocks/block_composite.frag"});
    expectMembers(program.id(), GL_BUFFER_VARIABLE, "blockTiles[0].",
                  {{"rect", offsetof(GpuBlockTile, rect)},
                   {"atlas", offsetof(GpuBlockTile, atlas)},
                   {"centreRadius", offsetof(GpuBlockTile, centreRadius)},
                   {"instance", offsetof(GpuBlockTile, instance)},
                   {"lampSlices", offsetof(GpuBlockTile, lampSlices)},
                   {"reproject[0]", offsetof(GpuBlockTile, reproject)}});
    EXPECT_EQ(topLevelArrayStride(program.id(), "blockTiles[0].rect"), static_cast<GLint>(sizeof(GpuBlockTile)));
    EXPECT_EQ(storageBinding(program.id(), "BlockTiles"), static_cast<GLint>(kBlockTilesBinding));
}

TEST_F(MediaGpuLayout, ParticleLightIsReadWhereTheLightingPassWritesIt) {
    const gpu::Program lighting = gpu::compileProgram({.compute = "media/particles/particle_lighting.comp"});
    const gpu::Program splats = gpu::compileProgram({.vertex = "media/particles/particle_splats.vert", .fragment = "media/particles/particle_splats.frag"});
    EXPECT_EQ(storageBinding(lighting.id(), "ParticleLight"), static_cast<GLint>(kParticleLightBinding));
    EXPECT_EQ(storageBinding(splats.id(), "ParticleLight"), static_cast<GLint>(kParticleLightBinding));
    EXPECT_EQ(storageBinding(lighting.id(), "Particles"), static_cast<GLint>(kParticlesBinding));
}

TEST_F(MediaGpuLayout, SliceViewsMatchGpuSliceViews) {
    // The host include as a host's mesh shader sees it, and inside the plugin's own programs.
    const gpu::Program host = gpu::compileProgram({.vertex = "opaque.vert", .fragment = "opaque.frag", .defines = {"MEDIA_LIGHT_TRANSMITTANCE"}});
    const gpu::Program particles = gpu::compileProgram({.vertex = "media/particles/particles.vert", .fragment = "media/particles/particles.frag"});
    // A sun from the vertex stage, its slices with a crop (slice_crop).
    const gpu::Program cropped = gpu::compileProgram(
        {.vertex = "opaque.vert", .fragment = "opaque.frag", .defines = {"MEDIA_LIGHT_TRANSMITTANCE", "MEDIA_SLICE_CROPS", "VERTEX_LIGHTS 1", "VERTEX_DIRECTIONAL_LIGHTS 1u"}});
    for (GLuint program : {host.id(), particles.id(), cropped.id()}) {
        const std::pair<const char*, std::size_t> members[] = {
            {"mediaSliceCount", offsetof(GpuSliceViews, count)},
            {"mediaLightSlices[0]", offsetof(GpuSliceViews, perLight)},
            {"mediaSliceViews[0].view", offsetof(GpuSliceViews, views)},
            {"mediaSliceViews[0].params2", offsetof(GpuSliceViews, views) + offsetof(gpu::GpuLightView, params2)},
            {"mediaSliceViews[1].view", offsetof(GpuSliceViews, views) + sizeof(gpu::GpuLightView)}};
        for (const auto& [name, offset] : members)
            EXPECT_EQ(gpu::test::resourceOffset(program, GL_UNIFORM, name), static_cast<GLint>(offset)) << name;
        EXPECT_EQ(gpu::test::resourceProperty(program, GL_UNIFORM, "mediaLightSlices[0]", GL_ARRAY_STRIDE),
                  static_cast<GLint>(sizeof(glm::ivec4)));
        EXPECT_EQ(gpu::test::blockSize(program, GL_UNIFORM_BLOCK, "MediaSliceViews"), static_cast<GLint>(sizeof(GpuSliceViews)));
        EXPECT_EQ(gpu::test::resourceProperty(program, GL_UNIFORM_BLOCK, "MediaSliceViews", GL_BUFFER_BINDING),
                  static_cast<GLint>(kSliceViewsBinding));
    }
}

// The multiple model's block and grid, in each pass family that reads them.
TEST_F(MediaGpuLayout, ScatteringMatchesGpuScattering) {
    const gpu::Program lighting = gpu::compileProgram({.compute = "media/particles/particle_lighting.comp", .defines = {"MEDIA_MULTIPLE"}});
    const gpu::Program raymarch = gpu::compileProgram({.vertex = "fullscreen.vert", .fragment = "media/raymarch/raymarch.frag", .defines = {"MEDIA_MULTIPLE"}});
    for (GLuint program : {lighting.id(), raymarch.id()}) {
        EXPECT_EQ(gpu::test::resourceOffset(program, GL_UNIFORM, "MediaScattering.gridMin"), static_cast<GLint>(offsetof(GpuScattering, gridMin)));
        EXPECT_EQ(gpu::test::resourceOffset(program, GL_UNIFORM, "MediaScattering.gridInvExtent"),
                  static_cast<GLint>(offsetof(GpuScattering, gridInvExtent)));
        EXPECT_EQ(gpu::test::blockSize(program, GL_UNIFORM_BLOCK, "MediaScattering"), static_cast<GLint>(sizeof(GpuScattering)));
        EXPECT_EQ(gpu::test::resourceProperty(program, GL_UNIFORM_BLOCK, "MediaScattering", GL_BUFFER_BINDING),
                  static_cast<GLint>(kScatteringBinding));
    }
}

TEST_F(MediaGpuLayout, VolumesMatchGpuVolume) {
    const gpu::Program program = gpu::compileProgram({.vertex = "fullscreen.vert", .fragment = "media/slices/volume_slices.frag"});
    expectMembers(program.id(), GL_BUFFER_VARIABLE, "volumes[0].",
                  {{"toUnit", offsetof(GpuVolume, toUnit)},
                   {"medium", offsetof(GpuVolume, medium)},
                   {"albedoG", offsetof(GpuVolume, albedoG)},
                   {"emission", offsetof(GpuVolume, emission)},
                   {"noise", offsetof(GpuVolume, noise)},
                   {"noiseShape", offsetof(GpuVolume, noiseShape)},
                   {"noiseScale", offsetof(GpuVolume, noiseScale)},
                   {"noiseOffset", offsetof(GpuVolume, noiseOffset)}});
    EXPECT_EQ(topLevelArrayStride(program.id(), "volumes[0].toUnit"), static_cast<GLint>(sizeof(GpuVolume)));
    EXPECT_EQ(storageBinding(program.id(), "MediaVolumes"), static_cast<GLint>(kVolumesBinding));
}

// The texture unit a sampler uniform is bound to in `program` (its layout(binding) value).
GLint samplerUnit(GLuint program, const char* sampler) {
    const GLint location = glGetUniformLocation(program, sampler);
    EXPECT_GE(location, 0) << sampler;
    GLint unit = -1;
    if (location >= 0) glGetUniformiv(program, location, &unit);
    return unit;
}

TEST_F(MediaGpuLayout, EveryBindingPointMatchesGpuBindings) {
    const gpu::Program composite = gpu::compileProgram(blockCompositeDesc(kBlockExactCut | kBlockOwnParticles | kBlockExactShading));
    EXPECT_EQ(samplerUnit(composite.id(), "uSceneDepth"), static_cast<GLint>(kSceneDepthUnit));
    EXPECT_EQ(samplerUnit(composite.id(), "uShadowDepth"), static_cast<GLint>(kShadowDepthUnit));
    EXPECT_EQ(samplerUnit(composite.id(), "mediaSlices"), static_cast<GLint>(kSlicesUnit));
    EXPECT_EQ(samplerUnit(composite.id(), "uImpostorDepths"), static_cast<GLint>(kImpostorDepthsUnit));
    EXPECT_EQ(samplerUnit(composite.id(), "uImpostorSums1"), static_cast<GLint>(kImpostorSums1Unit));
    EXPECT_EQ(samplerUnit(composite.id(), "uImpostorSums2"), static_cast<GLint>(kImpostorSums2Unit));
    EXPECT_EQ(samplerUnit(composite.id(), "uImpostorMoments"), static_cast<GLint>(kImpostorMomentsUnit));
    EXPECT_EQ(samplerUnit(composite.id(), "uSeamMask"), static_cast<GLint>(kSeamMaskUnit));
    EXPECT_EQ(storageBinding(composite.id(), "DrawOrder"), static_cast<GLint>(kDrawOrderBinding));
    const gpu::Program litComposite = gpu::compileProgram(blockCompositeDesc(kBlockExactCut | kBlockLitImpostor));
    EXPECT_EQ(samplerUnit(litComposite.id(), "uImpostorLit"), static_cast<GLint>(kImpostorLitUnit));
    const gpu::Program blockLighting = gpu::compileProgram(blockImpostorLightingDesc(true));
    EXPECT_EQ(samplerUnit(blockLighting.id(), "uImpostorDepths"), static_cast<GLint>(kImpostorDepthsUnit));
    EXPECT_EQ(samplerUnit(blockLighting.id(), "uImpostorSums1"), static_cast<GLint>(kImpostorSums1Unit));
    EXPECT_EQ(samplerUnit(blockLighting.id(), "uImpostorSums2"), static_cast<GLint>(kImpostorSums2Unit));
    EXPECT_EQ(samplerUnit(blockLighting.id(), "uImpostorMoments"), static_cast<GLint>(kImpostorMomentsUnit));
    EXPECT_EQ(samplerUnit(blockLighting.id(), "mediaSlices"), static_cast<GLint>(kSlicesUnit));
    EXPECT_EQ(storageBinding(blockLighting.id(), "DrawOrder"), static_cast<GLint>(kDrawOrderBinding));

    const gpu::Program lighting = gpu::compileProgram(particleLightingDesc({.exact = true, .meshCrossings = true}));
    EXPECT_EQ(storageBinding(lighting.id(), "SplatFlags"), static_cast<GLint>(kSplatFlagsBinding));
    EXPECT_EQ(storageBinding(lighting.id(), "ParticleLight"), static_cast<GLint>(kParticleLightBinding));
    const gpu::Program splats = gpu::compileProgram(particleSplatDesc({.lamps = true}));
    EXPECT_EQ(samplerUnit(splats.id(), "uKernelTable"), static_cast<GLint>(kKernelTableUnit));
    EXPECT_EQ(storageBinding(splats.id(), "LampNeighbourhoods"), static_cast<GLint>(kLampNeighbourhoodBinding));
    EXPECT_EQ(storageBinding(splats.id(), "Particles"), static_cast<GLint>(kParticlesBinding));
    const gpu::Program sheetSplats = gpu::compileProgram(sheetSplatDesc(true, false));
    EXPECT_EQ(samplerUnit(sheetSplats.id(), "uKernelTable"), static_cast<GLint>(kKernelTableUnit));
    EXPECT_EQ(samplerUnit(sheetSplats.id(), "uSceneDepth"), static_cast<GLint>(kSceneDepthUnit));
    EXPECT_EQ(storageBinding(sheetSplats.id(), "ParticleLight"), static_cast<GLint>(kParticleLightBinding));
    const gpu::Program sheetExact = gpu::compileProgram(LocalLightPrograms::withLocalLights(sheetExactDesc()));
    EXPECT_EQ(samplerUnit(sheetExact.id(), "uSceneDepth"), static_cast<GLint>(kSceneDepthUnit));
    EXPECT_EQ(samplerUnit(sheetExact.id(), "mediaSlices"), static_cast<GLint>(kSlicesUnit));
    EXPECT_EQ(storageBinding(sheetExact.id(), "LampNeighbourhoods"), static_cast<GLint>(kLampNeighbourhoodBinding));
    const gpu::Program sheetComposite = gpu::compileProgram(sheetCompositeDesc());
    EXPECT_EQ(samplerUnit(sheetComposite.id(), "uSheet"), static_cast<GLint>(kSheetUnit));
    const gpu::Program raymarch = gpu::compileProgram({.vertex = "fullscreen.vert", .fragment = "media/raymarch/raymarch.frag"});
    EXPECT_EQ(samplerUnit(raymarch.id(), "uScattering"), static_cast<GLint>(kVoxelScatteringUnit));
    EXPECT_EQ(samplerUnit(raymarch.id(), "uEmission"), static_cast<GLint>(kVoxelEmissionUnit));
    EXPECT_EQ(samplerUnit(raymarch.id(), "uSceneDepth"), static_cast<GLint>(kSceneDepthUnit));
    EXPECT_EQ(samplerUnit(raymarch.id(), "mediaSlices"), static_cast<GLint>(kSlicesUnit));
    const gpu::Program multiple = gpu::compileProgram({.vertex = "fullscreen.vert", .fragment = "media/raymarch/raymarch.frag", .defines = {"MEDIA_MULTIPLE"}});
    EXPECT_EQ(samplerUnit(multiple.id(), "uEnvironment"), static_cast<GLint>(kEnvironmentUnit));
    const gpu::Program lamps = gpu::compileProgram(LocalLightPrograms::withLocalLights(particlesDesc(true)));
    EXPECT_EQ(storageBinding(lamps.id(), "LampNeighbourhoods"), static_cast<GLint>(kLampNeighbourhoodBinding));

    const gpu::Program slices = gpu::compileProgram({.vertex = "media/blocks/block_slices.vert", .fragment = "media/blocks/block_slices.frag"});
    EXPECT_EQ(samplerUnit(slices.id(), "uImpostorDepths"), static_cast<GLint>(kImpostorDepthsUnit));
    EXPECT_EQ(samplerUnit(slices.id(), "uImpostorMoments"), static_cast<GLint>(kSliceImpostorMomentsUnit));
    EXPECT_EQ(storageBinding(slices.id(), "ImpostorItems"), static_cast<GLint>(kImpostorItemsBinding));
    EXPECT_EQ(storageBinding(slices.id(), "BlockTiles"), static_cast<GLint>(kBlockTilesBinding));

    const gpu::Program lampSlices = gpu::compileProgram({.vertex = "media/slices/light_slices.vert", .fragment = "media/slices/light_slices.frag",
                                                         .defines = {"SLICE_PARTICLE_LIST"}});
    EXPECT_EQ(storageBinding(lampSlices.id(), "LampSliceParticles"), static_cast<GLint>(kLampSliceParticlesBinding));
    const gpu::Program deposit =
        gpu::compileProgram({.vertex = "media/slices/light_slice_deposit.vert", .fragment = "media/slices/light_slice_deposit.frag"});
    EXPECT_EQ(storageBinding(deposit.id(), "SlicePieces"), static_cast<GLint>(kSlicePiecesBinding));
    const gpu::Program prefix = gpu::compileProgram({.vertex = "fullscreen.vert", .fragment = "media/slices/light_slice_prefix.frag", .defines = {"SLICES 4"}});
    EXPECT_EQ(samplerUnit(prefix.id(), "uSlabs"), static_cast<GLint>(kSlabsUnit));
    const gpu::Program intervals = gpu::compileProgram({.vertex = "fullscreen.vert", .fragment = "media/slices/light_slice_intervals.frag"});
    EXPECT_EQ(samplerUnit(intervals.id(), "uPacked"), static_cast<GLint>(kPackedSlicesUnit));
    const gpu::Program hostDepth = gpu::compileProgram({.vertex = "fullscreen.vert", .fragment = "media/frame/host_depth.frag"});
    EXPECT_EQ(samplerUnit(hostDepth.id(), "uHostDepth"), static_cast<GLint>(kHostDepthUnit));
    const gpu::Program stencil = gpu::compileProgram({.vertex = "fullscreen.vert", .fragment = "media/blocks/block_seam_stencil.frag"});
    EXPECT_EQ(samplerUnit(stencil.id(), "uSeamMask"), static_cast<GLint>(kSeamMaskUnit));
    const gpu::Program edges = gpu::compileProgram({.vertex = "fullscreen.vert", .fragment = "media/upsample/edge_stencil.frag"});
    EXPECT_EQ(samplerUnit(edges.id(), "uDepthUsed"), static_cast<GLint>(kDepthUsedUnit));
    EXPECT_EQ(samplerUnit(edges.id(), "uSceneDepth"), static_cast<GLint>(kSceneDepthUnit));
    const gpu::Program marks = gpu::compileProgram({.vertex = "media/upsample/seam_marks.vert", .fragment = "media/upsample/seam_marks.frag"});
    EXPECT_EQ(storageBinding(marks.id(), "SeamParticles"), static_cast<GLint>(kSeamParticlesBinding));
    EXPECT_EQ(storageBinding(marks.id(), "Particles"), static_cast<GLint>(kParticlesBinding));
    EXPECT_EQ(samplerUnit(marks.id(), "uReducedMedia"), static_cast<GLint>(kReducedMediaUnit));
    EXPECT_EQ(samplerUnit(marks.id(), "uSceneDepth"), static_cast<GLint>(kSceneDepthUnit));
    EXPECT_EQ(storageBinding(composite.id(), "BlockNeighbours"), static_cast<GLint>(kBlockNeighboursBinding));
}

}  // namespace
}  // namespace nimbus::media
