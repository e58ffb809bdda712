#pragma once
// Every binding point of the media plugin's shaders (GLSL twin: shaders/media/bindings.glsl; a test
// checks each against the compiled programs), and the one block a host's mesh shader shares with
// it: MediaSliceViews (shaders/media/host/light_transmittance.glsl).
//
// The plugin binds, before each of its draws, its own copies of the blocks of gpu/frame_layout.h
// (Frame 0, Lights 1, ShadowViews 2) packed from the HostFrame: a host's own blocks at those points
// are overwritten while the plugin runs, and must be rebound by the host afterwards.
#include <cstddef>

#include <glm/glm.hpp>

#include "nimbus/gpu/frame_layout.h"

namespace nimbus::media {

// Shared with the host's mesh shader (a host may move them: LightSlices::bind(binding, unit)).
inline constexpr GLuint kSliceViewsBinding = 3;  // MEDIA_SLICE_VIEWS_BINDING (uniform block)
inline constexpr GLuint kSlicesUnit = 2;         // MEDIA_SLICES_UNIT (sampler2DArray)
inline constexpr std::size_t kMaxHostLights = gpu::kMaxLights;  // MEDIA_MAX_LIGHTS

// Texture units.
inline constexpr GLuint kSlabsUnit = 0;           // MEDIA_SLABS_UNIT
inline constexpr GLuint kPackedSlicesUnit = 0;    // MEDIA_PACKED_SLICES_UNIT (light_slice_intervals.frag)
inline constexpr GLuint kHostDepthUnit = 0;       // MEDIA_HOST_DEPTH_UNIT
inline constexpr GLuint kDepthUsedUnit = 0;       // MEDIA_DEPTH_USED_UNIT (edge_stencil.frag)
inline constexpr GLuint kReducedMediaUnit = 0;    // MEDIA_REDUCED_MEDIA_UNIT (seam_marks.frag)
inline constexpr GLuint kSheetUnit = 0;           // MEDIA_SHEET_UNIT (sheet_composite.frag)
inline constexpr GLuint kSceneDepthUnit = 3;      // MEDIA_SCENE_DEPTH_UNIT
inline constexpr GLuint kShadowDepthUnit = 4;     // MEDIA_SHADOW_DEPTH_UNIT
inline constexpr GLuint kImpostorDepthsUnit = 5;  // MEDIA_IMPOSTOR_DEPTHS_UNIT
inline constexpr GLuint kImpostorSums1Unit = 6;   // MEDIA_IMPOSTOR_SUMS1_UNIT
inline constexpr GLuint kKernelTableUnit = 6;     // MEDIA_KERNEL_TABLE_UNIT (never with the impostors)
inline constexpr GLuint kImpostorSums2Unit = 7;   // MEDIA_IMPOSTOR_SUMS2_UNIT
inline constexpr GLuint kImpostorMomentsUnit = 8; // MEDIA_IMPOSTOR_MOMENTS_UNIT
inline constexpr GLuint kSliceImpostorMomentsUnit = 6;  // MEDIA_SLICE_IMPOSTOR_MOMENTS_UNIT (block_slices.frag)
inline constexpr GLuint kSeamMaskUnit = 9;        // MEDIA_SEAM_MASK_UNIT
inline constexpr GLuint kImpostorLitUnit = 13;    // MEDIA_IMPOSTOR_LIT_UNIT (blocks: the light per impostor texel)
inline constexpr GLuint kVoxelScatteringUnit = 5; // MEDIA_VOXEL_SCATTERING_UNIT (raymarch: never with the impostors)
inline constexpr GLuint kVoxelEmissionUnit = 7;   // MEDIA_VOXEL_EMISSION_UNIT
inline constexpr GLuint kEnvironmentUnit = 10;    // MEDIA_ENVIRONMENT_UNIT (multiple scattering)
inline constexpr GLuint kEnvironmentDirectionalUnit = 12;  // MEDIA_ENVIRONMENT_DIRECTIONAL_UNIT (its P1 anisotropy)
inline constexpr GLuint kNoiseGridUnit = 11;      // MEDIA_NOISE_GRID_UNIT (volume slices: the noise volumes' σ_t on a grid)
// Image units.
inline constexpr GLuint kGridScatteringImage = 0;  // raymarch_noise.comp: the raymarch grid's rgb σ_s, a σ_t
inline constexpr GLuint kGridEmissionImage = 1;    // its rgb σ_t·emission, a σ_t·g
inline constexpr GLuint kNoiseGridImage = 2;       // the noise volumes' σ_t alone

// Uniform blocks (0..2 are gpu/frame_layout.h's).
inline constexpr GLuint kScatteringBinding = 4;   // MEDIA_SCATTERING_BINDING (multiple scattering)

// Storage buffers.
inline constexpr GLuint kParticlesBinding = 3;           // MEDIA_PARTICLES_BINDING
inline constexpr GLuint kDrawOrderBinding = 5;           // MEDIA_DRAW_ORDER_BINDING
inline constexpr GLuint kImpostorItemsBinding = 6;       // MEDIA_IMPOSTOR_ITEMS_BINDING
inline constexpr GLuint kBlockTilesBinding = 7;          // MEDIA_BLOCK_TILES_BINDING
inline constexpr GLuint kLampNeighbourhoodBinding = 8;   // MEDIA_LAMP_NEIGHBOURHOODS_BINDING
inline constexpr GLuint kLampSliceParticlesBinding = 9;  // MEDIA_LAMP_SLICE_PARTICLES_BINDING
inline constexpr GLuint kParticleLightBinding = 10;      // MEDIA_PARTICLE_LIGHT_BINDING
inline constexpr GLuint kBlockNeighboursBinding = 10;    // MEDIA_BLOCK_NEIGHBOURS_BINDING (blocks mode only)
inline constexpr GLuint kSlicePiecesBinding = 11;        // MEDIA_SLICE_PIECES_BINDING
inline constexpr GLuint kVolumesBinding = 12;            // MEDIA_VOLUMES_BINDING
inline constexpr GLuint kSplatFlagsBinding = 13;         // MEDIA_SPLAT_FLAGS_BINDING (per-particle splat variants)
inline constexpr GLuint kSplatRanksBinding = 14;         // MEDIA_SPLAT_RANKS_BINDING (the edges' redraw)
inline constexpr GLuint kSeamParticlesBinding = 15;      // MEDIA_SEAM_PARTICLES_BINDING (the seam marks)

// The MediaSliceViews uniform block.
struct alignas(16) GpuSliceViews {
    glm::ivec4 count;                           // x: slice views this frame; y, z, w: the lamp views' layout (frame_blocks.cpp sliceHeader)
    glm::ivec4 perLight[kMaxHostLights];        // x: first view (−1: none), y: view count
    gpu::GpuLightView views[gpu::kMaxLightViews];
};

// The MediaScattering uniform block (shaders/media/common/multiple_scattering.glsl).
struct alignas(16) GpuScattering {
    glm::vec4 gridMin{0.0f};        // xyz origin-relative corner of the environment grid
    glm::vec4 gridInvExtent{0.0f};  // xyz 1 / its extent
};

// One volume of the MediaVolumes storage buffer (shaders/media/common/volumes.glsl, volume.h).
struct alignas(16) GpuVolume {
    glm::mat4 toUnit{1.0f};     // frame-relative world → the node's frame scaled to the unit cube [−1, 1]³ or unit sphere
    glm::vec4 medium{0.0f};     // x σ_t (1/m), y shape (0 box, 1 ellipsoid), z 1 with noise
    glm::vec4 albedoG{0.0f};    // rgb albedo, w g
    glm::vec4 emission{0.0f};   // rgb emitted radiance per unit optical depth
    glm::uvec4 noise{0u};       // NoiseParams kind, octaves, seed
    glm::vec4 noiseShape{0.0f}; // NoiseParams gain, invAmplitude, coverage, invOneMinusCoverage
    glm::vec4 noiseScale{0.0f}; // xyz unit frame → noise space (half size × frequency), w NoiseParams invFalloff
    glm::vec4 noiseOffset{0.0f};// xyz noise space offset (−drift × frequency)
};

}  // namespace nimbus::media
