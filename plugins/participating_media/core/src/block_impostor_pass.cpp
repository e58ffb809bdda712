// Depth impostors of blocks (seed 000 §2.1): every particle drawn once into its block's atlas tile,
// blending MIN for the front/back depths and ADD for optical depth in the same pass.
#include <algorithm>
#include <numeric>

#include <glm/gtc/type_ptr.hpp>

#include "block_passes.h"
#include "nimbus/gpu/shader_program.h"

namespace nimbus::media {
namespace {

void ensure(gpu::Buffer& buffer, std::size_t& capacity, std::size_t bytes) {
    if (buffer && capacity >= bytes) return;
    capacity = std::max(bytes, capacity * 3 / 2);
    buffer = gpu::createBuffer(capacity, nullptr, GL_DYNAMIC_STORAGE_BIT);
}

}  // namespace

BlockViewPlan planBlockView(const BlockPartition& partition, const ImpostorView& view, const glm::dvec3& origin, float scale,
                            int maxAtlasSize, const std::vector<std::uint8_t>& notDrawn) {
    BlockViewPlan plan;
    plan.view = view;
    const std::vector<BlockFootprint> footprints = blockFootprints(partition, view, origin);
    std::vector<glm::ivec2> sizes = tileSizes(footprints, view.viewport, scale);
    for (std::size_t b = 0; b < notDrawn.size() && b < sizes.size(); ++b)
        if (notDrawn[b] != 0) sizes[b] = glm::ivec2(0);
    const AtlasLayout layout = packAtlas(sizes, maxAtlasSize);
    plan.atlasSize = glm::ivec2(layout.width, layout.height);
    plan.tiles.resize(partition.blocks.size());
    for (std::size_t b = 0; b < partition.blocks.size(); ++b) {
        const AtlasTile& t = layout.tiles[b];
        plan.tiles[b].rect = footprints[b].rect;
        plan.tiles[b].atlas = glm::vec4(static_cast<float>(t.x), static_cast<float>(t.y), static_cast<float>(t.width),
                                        static_cast<float>(t.height));
        plan.tiles[b].centreRadius = glm::vec4(glm::vec3(partition.blocks[b].centre - origin), partition.blocks[b].meanParticleRadius);
        // Texel centres are pixel centres when the snapped rectangle's pixels are the tile's texels.
        const glm::vec2 pixels = glm::round(rectanglePixels(footprints[b].rect, view.viewport));
        const bool onPixelGrid = t.width > 0 && pixels == glm::vec2(static_cast<float>(t.width), static_cast<float>(t.height));
        // Items are uploaded block by block in partition order (uploadItems), so a block's items
        // are its slice of `order`. Floats hold the indices exactly up to 2^24; beyond, no list.
        const Block& block = partition.blocks[b];
        const bool listed = std::uint64_t{block.first} + block.count <= (std::uint64_t{1} << 24);
        plan.tiles[b].instance = glm::vec4(0.0f, onPixelGrid ? 1.0f : 0.0f, listed ? static_cast<float>(block.first) : 0.0f,
                                           listed ? static_cast<float>(block.count) : 0.0f);
    }
    return plan;
}

BlockViewPlan planInstancedBlockView(const BlockPartition& partition, std::size_t prototype, const ImpostorView& view,
                                     const glm::dvec3& origin, float scale, int maxAtlasSize) {
    // Every instance has the prototype's shape: its sphere around its own centre.
    BlockPartition shapes = partition;
    for (Block& b : shapes.blocks) b.radius = partition.blocks[prototype].radius;
    BlockViewPlan plan;
    plan.view = view;
    const std::vector<BlockFootprint> footprints = blockFootprints(shapes, view, origin);
    std::vector<glm::ivec2> sizes(footprints.size(), glm::ivec2(0));
    sizes[prototype] = tileSizes({footprints[prototype]}, view.viewport, scale).front();
    const AtlasLayout layout = packAtlas(sizes, maxAtlasSize);
    const AtlasTile& t = layout.tiles[prototype];
    plan.atlasSize = glm::ivec2(layout.width, layout.height);
    const glm::dmat4 viewMatrix(view.view);
    auto distance = [&](const glm::dvec3& centre) {
        const glm::dvec3 c(viewMatrix * glm::dvec4(centre - origin, 1.0));
        return view.perspective ? glm::length(c - glm::dvec3(viewMatrix * glm::dvec4(glm::dvec3(view.eye), 1.0))) : -c.z;
    };
    const double prototypeDistance = distance(partition.blocks[prototype].centre);
    plan.tiles.resize(partition.blocks.size());
    for (std::size_t b = 0; b < partition.blocks.size(); ++b) {
        GpuBlockTile& tile = plan.tiles[b];
        tile.rect = footprints[b].rect;
        const bool visible = tile.rect.z > tile.rect.x && t.width > 0;
        tile.atlas = visible ? glm::vec4(static_cast<float>(t.x), static_cast<float>(t.y), static_cast<float>(t.width),
                                         static_cast<float>(t.height))
                             : glm::vec4(0.0f);
        tile.centreRadius = glm::vec4(glm::vec3(partition.blocks[b].centre - origin), partition.blocks[prototype].meanParticleRadius);
        tile.instance = glm::vec4(static_cast<float>(distance(partition.blocks[b].centre) - prototypeDistance), 0.0f, 0.0f, 0.0f);
    }
    // The prototype's own tile must exist for its impostor to be rendered, even when it is off-view.
    if (t.width > 0) plan.tiles[prototype].atlas = glm::vec4(static_cast<float>(t.x), static_cast<float>(t.y),
                                                             static_cast<float>(t.width), static_cast<float>(t.height));
    return plan;
}

std::size_t choosePrototype(const BlockPartition& partition) {
    std::vector<std::size_t> order(partition.blocks.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return partition.blocks[a].radius < partition.blocks[b].radius; });
    return order.empty() ? 0 : order[order.size() / 2];
}

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

BlockImpostorRenderer::BlockImpostorRenderer() {
    program_ = gpu::compileProgram({.vertex = "media/block_impostors.vert", .fragment = "media/block_impostors.frag"});
}

void BlockImpostorRenderer::render(const BlockViewPlan& plan, std::size_t tileSet, const ImpostorTargets& targets,
                                   const BlockGpuBuffers& blocks, const ParticleGpuBuffer& particles) const {
    gpu::Framebuffer fbo = gpu::createFramebuffer();
    const GLuint textures[4] = {targets.depths, targets.sums1, targets.sums2, targets.moments};
    GLenum drawBuffers[4];
    for (GLuint i = 0; i < 4; ++i) {
        if (textures[i] != 0) glNamedFramebufferTexture(fbo.id(), GL_COLOR_ATTACHMENT0 + i, textures[i], 0);
        drawBuffers[i] = textures[i] != 0 ? GL_COLOR_ATTACHMENT0 + i : GL_NONE;
    }
    glNamedFramebufferDrawBuffers(fbo.id(), 4, drawBuffers);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
    // Front and −back start at +∞ for MIN; optical depth and the sums start at 0.
    const float far[4] = {3.0e38f, 3.0e38f, 3.0e38f, 0.0f}, zero[4] = {0, 0, 0, 0};
    glClearNamedFramebufferfv(fbo.id(), GL_COLOR, 0, far);
    for (GLint i = 1; i < 4; ++i)
        if (textures[i] != 0) glClearNamedFramebufferfv(fbo.id(), GL_COLOR, i, zero);
    glViewport(0, 0, plan.atlasSize.x, plan.atlasSize.y);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glEnable(GL_BLEND);
    glBlendEquationSeparatei(0, GL_MIN, GL_FUNC_ADD);  // seed 000 §2.1: min for depths, a separate alpha equation
    glBlendFunci(0, GL_ONE, GL_ONE);
    glBlendEquationi(1, GL_FUNC_ADD);
    glBlendFunci(1, GL_ONE, GL_ONE);
    glBlendEquationi(2, GL_FUNC_ADD);
    glBlendFunci(2, GL_ONE, GL_ONE);
    glBlendEquationi(3, GL_FUNC_ADD);
    glBlendFunci(3, GL_ONE, GL_ONE);
    for (GLenum plane = 0; plane < 4; ++plane) glEnable(GL_CLIP_DISTANCE0 + plane);

    const GLuint program = program_.id();
    glUseProgram(program);
    particles.bindParticles();
    blocks.bind(tileSet);
    const glm::mat4 projection = plan.view.viewProjection * glm::inverse(plan.view.view);
    // Views are symmetric: their half extent is the projection's scale (media/view_rays.glsl).
    const glm::vec2 halfExtent(1.0f / projection[0][0], 1.0f / projection[1][1]);
    const glm::vec4 params(plan.view.perspective ? 1.0f : 0.0f, plan.view.nearDepth, 0.0f, 0.0f);
    const glm::vec2 atlas(plan.atlasSize);
    glProgramUniformMatrix4fv(program, 0, 1, GL_FALSE, glm::value_ptr(plan.view.view));
    glProgramUniformMatrix4fv(program, 1, 1, GL_FALSE, glm::value_ptr(projection));
    glProgramUniform4fv(program, 2, 1, glm::value_ptr(params));
    glProgramUniform2fv(program, 3, 1, glm::value_ptr(atlas));
    glProgramUniform2fv(program, 4, 1, glm::value_ptr(halfExtent));
    glProgramUniform3fv(program, 5, 1, glm::value_ptr(plan.view.eye));
    glBindVertexArray(vertexArray_.id());
    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(blocks.itemCount()));
    glBindVertexArray(0);

    for (GLenum plane = 0; plane < 4; ++plane) glDisable(GL_CLIP_DISTANCE0 + plane);
    glBlendEquation(GL_FUNC_ADD);
    glDisable(GL_BLEND);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

BlockImpostorAtlas addBlockImpostorPass(render::FrameGraph& graph, const BlockViewPlan& plan, const BlockGpuBuffers& blocks,
                                        const ParticleGpuBuffer& particles, const BlockImpostorRenderer& impostors) {
    const glm::ivec2 atlas = plan.atlasSize;
    return graph.addPass<BlockImpostorAtlas>(
        "block_impostors",
        [&](render::PassBuilder& builder, BlockImpostorAtlas& d) {
            d.depths = builder.create("block_impostor_depths", {GL_TEXTURE_2D, GL_RGBA32F, atlas.x, atlas.y, 1, 1});
            d.sums1 = builder.create("block_impostor_sums1", {GL_TEXTURE_2D, GL_RGBA32F, atlas.x, atlas.y, 1, 1});
            d.sums2 = builder.create("block_impostor_sums2", {GL_TEXTURE_2D, GL_RGBA32F, atlas.x, atlas.y, 1, 1});
            d.moments = builder.create("block_impostor_moments", {GL_TEXTURE_2D, GL_RG32F, atlas.x, atlas.y, 1, 1});
        },
        [&plan, &blocks, &particles, &impostors](const render::PassResources& r, const BlockImpostorAtlas& d) {
            impostors.render(plan, 0,
                             {.depths = r.id(d.depths), .sums1 = r.id(d.sums1), .sums2 = r.id(d.sums2), .moments = r.id(d.moments)},
                             blocks, particles);
        });
}

}  // namespace nimbus::media
