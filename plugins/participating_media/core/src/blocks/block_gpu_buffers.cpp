#include "blocks/block_gpu_buffers.h"

#include <algorithm>

namespace nimbus::media {
namespace {

void ensure(gpu::Buffer& buffer, std::size_t& capacity, std::size_t bytes) {
    if (buffer && capacity >= bytes) return;
    capacity = std::max(bytes, capacity * 3 / 2);
    buffer = gpu::createBuffer(capacity, nullptr, GL_DYNAMIC_STORAGE_BIT);
}

}  // namespace

void BlockGpuBuffers::uploadItems(const BlockPartition& partition) { uploadItems(partition, partition.blocks.size()); }

void BlockGpuBuffers::uploadItems(const BlockPartition& partition, std::size_t onlyBlock) {
    std::vector<glm::uvec2> items;
    items.reserve(partition.order.size());
    for (std::size_t b = 0; b < partition.blocks.size(); ++b) {
        if (onlyBlock < partition.blocks.size() && b != onlyBlock) continue;
        for (std::uint32_t k = 0; k < partition.blocks[b].count; ++k)
            items.emplace_back(partition.order[partition.blocks[b].first + k], static_cast<std::uint32_t>(b));
    }
    items_ = items.size();
    ensure(itemBuffer_, itemCapacity_, std::max<std::size_t>(items.size(), 1) * sizeof(glm::uvec2));
    if (!items.empty()) glNamedBufferSubData(itemBuffer_.id(), 0, static_cast<GLsizeiptr>(items.size() * sizeof(glm::uvec2)), items.data());
}

void BlockGpuBuffers::uploadTileSets(const std::vector<const BlockViewPlan*>& plans) {
    GLint alignment = 256;
    glGetIntegerv(GL_SHADER_STORAGE_BUFFER_OFFSET_ALIGNMENT, &alignment);
    const auto align = static_cast<std::size_t>(std::max(alignment, 1));
    tileRanges_.clear();
    std::size_t total = 0;
    for (const BlockViewPlan* plan : plans) {
        const std::size_t bytes = std::max<std::size_t>(plan->tiles.size(), 1) * sizeof(GpuBlockTile);
        tileRanges_.emplace_back(total, bytes);
        total += (bytes + align - 1) / align * align;
    }
    ensure(tileBuffer_, tileCapacity_, std::max<std::size_t>(total, 1));
    for (std::size_t i = 0; i < plans.size(); ++i)
        if (!plans[i]->tiles.empty())
            glNamedBufferSubData(tileBuffer_.id(), static_cast<GLintptr>(tileRanges_[i].first),
                                 static_cast<GLsizeiptr>(plans[i]->tiles.size() * sizeof(GpuBlockTile)), plans[i]->tiles.data());
}

void BlockGpuBuffers::uploadDrawOrder(const std::vector<std::uint32_t>& blocks) {
    ensure(orderBuffer_, orderCapacity_, std::max<std::size_t>(blocks.size(), 1) * sizeof(std::uint32_t));
    if (!blocks.empty())
        glNamedBufferSubData(orderBuffer_.id(), 0, static_cast<GLsizeiptr>(blocks.size() * sizeof(std::uint32_t)), blocks.data());
}

void BlockGpuBuffers::uploadOrderNeighbours(const std::vector<glm::uvec2>& lists) {
    ensure(neighbourBuffer_, neighbourCapacity_, std::max<std::size_t>(lists.size(), 1) * sizeof(glm::uvec2));
    if (!lists.empty())
        glNamedBufferSubData(neighbourBuffer_.id(), 0, static_cast<GLsizeiptr>(lists.size() * sizeof(glm::uvec2)), lists.data());
}

void BlockGpuBuffers::uploadLampSliceParticles(const std::vector<std::uint32_t>& particles) {
    lampSliceParticles_ = particles.size();
    ensure(lampSliceBuffer_, lampSliceCapacity_, std::max<std::size_t>(particles.size(), 1) * sizeof(std::uint32_t));
    if (!particles.empty())
        glNamedBufferSubData(lampSliceBuffer_.id(), 0, static_cast<GLsizeiptr>(particles.size() * sizeof(std::uint32_t)), particles.data());
}

void BlockGpuBuffers::bindLampSliceParticles() const {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kLampSliceParticlesBinding, lampSliceBuffer_.id());
}

void BlockGpuBuffers::bind(std::size_t tileSet) const {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kImpostorItemsBinding, itemBuffer_.id());
    const auto& [offset, bytes] = tileRanges_.at(tileSet);
    glBindBufferRange(GL_SHADER_STORAGE_BUFFER, kBlockTilesBinding, tileBuffer_.id(), static_cast<GLintptr>(offset),
                      static_cast<GLsizeiptr>(bytes));
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kDrawOrderBinding, orderBuffer_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kBlockNeighboursBinding, neighbourBuffer_.id());
}

}  // namespace nimbus::media
