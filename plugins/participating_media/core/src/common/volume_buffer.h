#pragma once
// The GPU copy of the frame's volumes: one std430 storage buffer of GpuVolume
// (shaders/media/common/volumes.glsl), relative to the frame origin.
//
// Does not: hold particles (particle_buffer.h), or upload anything when there is no volume.
#include <vector>

#include <glm/glm.hpp>

#include "nimbus/gpu/gl_objects.h"
#include "nimbus/media/gpu_bindings.h"
#include "nimbus/media/volume.h"

namespace nimbus::media {

// A volume as the shaders read it: toUnit maps frame-relative world points to the unit cube or sphere.
GpuVolume packVolume(const Volume& volume, const glm::dvec3& origin);

class VolumeGpuBuffer {
public:
    // Rewrites the buffer (grows it when needed).
    void upload(const std::vector<Volume>& volumes, const glm::dvec3& origin);
    void bind() const { glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kVolumesBinding, buffer_.id()); }
    int count() const { return count_; }

private:
    gpu::Buffer buffer_;
    std::size_t capacity_ = 0;
    int count_ = 0;
    std::vector<GpuVolume> staging_;
};

}  // namespace nimbus::media
