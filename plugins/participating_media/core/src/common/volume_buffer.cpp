#include "common/volume_buffer.h"

#include <algorithm>

#include <glm/gtc/matrix_transform.hpp>

namespace nimbus::media {

GpuVolume packVolume(const Volume& volume, const glm::dvec3& origin) {
    // In double until the end: the origin's translation and the node's cancel there.
    const glm::dmat4 toUnit = glm::scale(glm::dmat4(1.0), 2.0 / volume.size) * volume.toLocal * glm::translate(glm::dmat4(1.0), origin);
    GpuVolume out;
    out.toUnit = glm::mat4(toUnit);
    out.medium = glm::vec4(static_cast<float>(volume.sigma()), volume.shape == VolumeShape::Ellipsoid ? 1.0f : 0.0f, volume.noise ? 1.0f : 0.0f, 0.0f);
    out.albedoG = glm::vec4(volume.medium.albedo, volume.medium.g);
    out.emission = glm::vec4(volume.medium.emission, 0.0f);
    if (volume.noise) {
        const NoiseParams& n = volume.noiseParams;
        out.noise = glm::uvec4(n.kind, n.octaves, n.seed, 0u);
        out.noiseShape = glm::vec4(n.gain, n.invAmplitude, n.coverage, n.invOneMinusCoverage);
        out.noiseScale = glm::vec4(glm::vec3(0.5 * volume.size * volume.noise->frequency), n.invFalloff);
        out.noiseOffset = glm::vec4(glm::vec3(-volume.drift * volume.noise->frequency), 0.0f);
    }
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
