#version 450 core
// The noise volumes into the raymarch grid (raymarch/raymarch_noise_pass.cpp): at each voxel centre
// of one volume's box, its density (media/common/noise.glsl, the same bits as the reference's C++)
// times σ, added to the grid's scattering and emission and to the noise grid the volume slices
// march. One dispatch per noise volume; a voxel is touched once per dispatch.
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;
#include "media/bindings.glsl"
#include "media/common/volumes.glsl"

layout(binding = MEDIA_GRID_SCATTERING_IMAGE, rgba32f) uniform image3D uScattering;  // rgb σ_t·albedo, a σ_t
layout(binding = MEDIA_GRID_EMISSION_IMAGE, rgba32f) uniform image3D uEmission;      // rgb σ_t·emission, a σ_t·g
layout(binding = MEDIA_NOISE_GRID_IMAGE, r32f) uniform image3D uNoise;                // the noise volumes' σ_t

layout(location = 0) uniform vec3 uGridCorner;  // frame-relative corner of voxel 0
layout(location = 1) uniform float uVoxel;
layout(location = 2) uniform ivec3 uFirst;      // the volume's first voxel
layout(location = 3) uniform ivec3 uLast;       // and its last, inclusive
layout(location = 4) uniform int uVolume;

void main() {
    ivec3 id = uFirst + ivec3(gl_GlobalInvocationID);
    if (any(greaterThan(id, uLast))) return;
    vec3 centre = uGridCorner + (vec3(id) + 0.5) * uVoxel;
    vec3 unit = (volumes[uVolume].toUnit * vec4(centre, 1.0)).xyz;
    if (!volumeInside(uVolume, unit)) return;
    float sigma = volumes[uVolume].medium.x * volumeNoiseDensity(uVolume, unit);
    if (!(sigma > 0.0)) return;
    vec4 albedoG = volumes[uVolume].albedoG;
    imageStore(uScattering, id, imageLoad(uScattering, id) + vec4(albedoG.rgb * sigma, sigma));
    imageStore(uEmission, id, imageLoad(uEmission, id) + vec4(volumes[uVolume].emission.rgb * sigma, albedoG.w * sigma));
    imageStore(uNoise, id, imageLoad(uNoise, id) + vec4(sigma));
}
