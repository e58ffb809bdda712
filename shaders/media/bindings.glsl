// Every binding point the media plugin's shaders use (C++ twin: nimbus/media/gpu_bindings.h; a test
// checks each against the compiled programs). A host may move the two its mesh shader shares with
// the plugin by defining them before including media/host/light_transmittance.glsl.
#ifndef MEDIA_SLICE_VIEWS_BINDING
#define MEDIA_SLICE_VIEWS_BINDING 3  // uniform block MediaSliceViews
#endif
#ifndef MEDIA_SLICES_UNIT
#define MEDIA_SLICES_UNIT 2          // sampler2DArray of the light slices, two planes to a layer beside their predecessors
#endif
#define MEDIA_SCENE_DEPTH_UNIT 3     // the host's scene depth (reversed Z)
#define MEDIA_SHADOW_DEPTH_UNIT 4    // the host's mesh shadow map, read as raw depth
#define MEDIA_IMPOSTOR_DEPTHS_UNIT 5
#define MEDIA_IMPOSTOR_SUMS1_UNIT 6
#define MEDIA_KERNEL_TABLE_UNIT 6
#define MEDIA_IMPOSTOR_SUMS2_UNIT 7
#define MEDIA_IMPOSTOR_MOMENTS_UNIT 8
#define MEDIA_SLICE_IMPOSTOR_MOMENTS_UNIT 6  // block_slices.frag
#define MEDIA_SEAM_MASK_UNIT 9
#define MEDIA_IMPOSTOR_LIT_UNIT 13    // blocks: the light shaded per impostor texel (block_impostor_lighting.frag)
#define MEDIA_VOXEL_SCATTERING_UNIT 5  // raymarch: rgb σ_t·albedo, a σ_t (sampler3D)
#define MEDIA_VOXEL_EMISSION_UNIT 7    // raymarch: rgb σ_t·emission, a σ_t·g
#define MEDIA_SLABS_UNIT 0
#define MEDIA_PACKED_SLICES_UNIT 0    // light_slice_intervals.frag: the slices as the slice passes wrote them
#define MEDIA_HOST_DEPTH_UNIT 0       // a standard-Z host depth, re-encoded by media_host_depth
#define MEDIA_DEPTH_USED_UNIT 0       // edge_stencil.frag: the depth each reduced media texel used
#define MEDIA_REDUCED_MEDIA_UNIT 0    // seam_marks.frag: the reduced media target
#define MEDIA_SHEET_UNIT 0            // sheets: one sheet's sums (sheet_composite.frag)
#define MEDIA_ENVIRONMENT_UNIT 10     // multiple scattering: the environment grid (sampler3D)
#define MEDIA_ENVIRONMENT_DIRECTIONAL_UNIT 12  // multiple scattering: the grid's P1 anisotropy (sampler3D)
#define MEDIA_NOISE_GRID_UNIT 11      // volume slices: the noise volumes' σ_t on the raymarch grid (sampler3D)
// Image units.
#define MEDIA_GRID_SCATTERING_IMAGE 0  // raymarch_noise.comp: rgb σ_s, a σ_t
#define MEDIA_GRID_EMISSION_IMAGE 1    // rgb σ_t·emission, a σ_t·g
#define MEDIA_NOISE_GRID_IMAGE 2       // the noise volumes' σ_t alone
// Uniform blocks (0..2 are gpu/frame_layout.h's, 3 MediaSliceViews above).
#define MEDIA_SCATTERING_BINDING 4    // multiple scattering: MediaScattering
// Storage buffers.
#define MEDIA_PARTICLES_BINDING 3
#define MEDIA_DRAW_ORDER_BINDING 5
#define MEDIA_IMPOSTOR_ITEMS_BINDING 6
#define MEDIA_BLOCK_TILES_BINDING 7
#define MEDIA_LAMP_NEIGHBOURHOODS_BINDING 8
#define MEDIA_LAMP_SLICE_PARTICLES_BINDING 9
#define MEDIA_PARTICLE_LIGHT_BINDING 10
#define MEDIA_BLOCK_NEIGHBOURS_BINDING 10
#define MEDIA_SLICE_PIECES_BINDING 11
#define MEDIA_VOLUMES_BINDING 12
#define MEDIA_SPLAT_FLAGS_BINDING 13  // per particle: the splats' variant bits (particle_lighting.comp MEDIA_SPLAT_FLAGS)
#define MEDIA_SPLAT_RANKS_BINDING 14  // the draw ranks a splat draw takes (particle_splats.vert SPLAT_RANK_LIST)
#define MEDIA_SEAM_PARTICLES_BINDING 15  // the particles a mesh enters (seam_marks.vert)
