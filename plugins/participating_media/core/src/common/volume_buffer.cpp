#include "common/volume_buffer.h"

#include <algorithm>

#include <glm/gtc/matrix_transform.hpp>

namespace nimbus::media {

GpuVolume packVolume(const Volume& volume, const glm::dvec3& origin) {
    // In double until the end: the origin's translation and the node's cancel there.
    const glm::dmat4 toUnit = glm::scale(glm::dmat4(1.0), 2.0 / volume.size) * volume.toLocal * glm::translate(glm::dmat4(1.0), origin);
    GpuVolume out;
    out.toUnit = glm::mat4(toUnit);
    out.medium = glm::vec4(static_cast<float>(volume.sigma()), volume.shape == VolumeShape::Ellipsoid ? 1.0f : 0.0f, 0.0f, 0.0f);
    return out;
}

void VolumeGpuBuffer::upload(const std::vector<Volume>& volumes, const glm::dvec3& origin) {
    count_ = static_cast<int>(volumes.size());
    if (volumes.empty()) return;
    staging_.clear();
    for (const Volume& v : volumes) staging_.push_back(packVolume(v, origin));
    const std::size_t bytes = staging_.size() * sizeof(GpuVolume);
    if (!buffer_ || capacity_ < bytes) {
        capacity_ = std::max(bytes, capacity_ * 3 / 2);
        buffer_ = gpu::createBuffer(capacity_, nullptr, GL_DYNAMIC_STORAGE_BIT);
    }
    glNamedBufferSubData(buffer_.id(), 0, static_cast<GLsizeiptr>(bytes), staging_.data());
}

}  // namespace nimbus::media
