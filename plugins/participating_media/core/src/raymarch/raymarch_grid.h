#pragma once
// The raymarch grid on the GPU: the CPU grid (voxel_grid.h: particles and constant volumes)
// uploaded into two RGBA32F 3D textures, which raymarch_noise then adds the noise volumes to, and an
// R32F texture of the noise volumes' σ_t alone, which the volume slices march for their light.
//
// Does not: evaluate noise (raymarch_noise_pass.h does, on the GPU) or keep the CPU grid.
#include <glm/glm.hpp>

#include "nimbus/gpu/gl_objects.h"
#include "raymarch/voxel_grid.h"

namespace nimbus::media {

class RaymarchGrid {
public:
    // Writes `grid` (textures remade when its size changes) and clears the noise texture.
    void upload(const VoxelGrid& grid);
    const gpu::Texture& scattering() const { return scattering_; }  // rgb σ_t·albedo, a σ_t
    const gpu::Texture& emission() const { return emission_; }      // rgb σ_t·emission, a σ_t·g
    const gpu::Texture& noise() const { return noise_; }            // the noise volumes' σ_t

private:
    gpu::Texture scattering_, emission_, noise_;
};

// A 3D texture clamped at its edges and read trilinearly.
gpu::Texture makeGridTexture(glm::ivec3 size, GLenum format);

}  // namespace nimbus::media
