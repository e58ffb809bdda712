#include "blocks/block_impostor_cache.h"

#include <algorithm>
#include <tuple>

namespace nimbus::media {
namespace {

bool sameLight(const Light& a, const Light& b) {
    return std::tie(a.kind, a.position, a.direction, a.radiance, a.range, a.innerConeAngle, a.outerConeAngle) ==
           std::tie(b.kind, b.position, b.direction, b.radiance, b.range, b.innerConeAngle, b.outerConeAngle);
}

bool sameBox(const OccluderBox& a, const OccluderBox& b) {
    return a.centre == b.centre && a.half == b.half && a.axis[0] == b.axis[0] && a.axis[1] == b.axis[1] && a.axis[2] == b.axis[2];
}

bool sameParticles(const ParticleSet& a, const ParticleSet& b) {
    return a.position == b.position && a.radius == b.radius && a.sigma == b.sigma && a.albedo == b.albedo && a.emission == b.emission &&
           a.g == b.g && a.phase == b.phase;
}

// Every shared setting but the mode's own (compared as BlocksSettings).
auto sharedFields(const MediaRenderSettings& s) {
    return std::tie(s.mode, s.slices, s.sliceResolution, s.sliceTexelsPerRadius, s.slicesNearMeshes, s.sliceTexelsPerRadiusNearMeshes,
                    s.sliceDeposit, s.mediaScale, s.mediaScaleAuto,
                    s.upsampleThreshold, s.upsampleOnly, s.noMeshCuts, s.scatteringVoxels, s.scatteringSweeps);
}

auto ownFields(const BlocksSettings& s) {
    return std::tie(s.blocks, s.impostorScale, s.instancing, s.blockShading, s.lighting, s.reuseDegrees);
}

// A texture of `desc`, made again only when its size or format changes.
void fit(gpu::Texture& texture, const gpu::TextureDesc& desc) {
    if (!texture || !(texture.desc() == desc)) texture = gpu::Texture(desc);
}

}  // namespace

bool sameSources(const ImpostorSources& a, const ImpostorSources& b) {
    return std::equal(a.lights.begin(), a.lights.end(), b.lights.begin(), b.lights.end(), sameLight) &&
           std::equal(a.occluders.begin(), a.occluders.end(), b.occluders.begin(), b.occluders.end(), sameBox) &&
           a.ambient == b.ambient && a.multiple == b.multiple && a.target == b.target && sharedFields(a.shared) == sharedFields(b.shared) &&
           ownFields(a.own) == ownFields(b.own);
}

ReuseDecision BlockImpostorCache::decide(const ParticleSet& particles, ImpostorSources sources, const std::vector<std::uint8_t>& builds,
                                         const BlockPartition& partition, const WorldView& view, const ImpostorReuseLimits& limits,
                                         BlockViewPlan& plan) {
    ReuseDecision decision;
    const bool same = sourcesKept_ && sameSources(sources, sources_) && sameParticles(particles, particles_);
    decision.light = same && lightKept_;
    if (same && cameraKept_ && builds == builds_) decision.camera = reuseCameraTiles(partition, plan_, view_, view, limits, plan);
    if (!same) {
        particles_ = particles;
        sources_ = std::move(sources);
        sourcesKept_ = true;
        lightKept_ = false;
    }
    if (decision.camera == ReuseVerdict::Reused) return decision;
    builds_ = builds;
    plan_ = plan;
    view_ = view;
    cameraKept_ = true;
    const glm::ivec2 size = plan.atlasSize, lit = (size + (kTileAlignment - 1)) / kTileAlignment;
    fit(depths_, {GL_TEXTURE_2D, GL_RGBA32F, size.x, size.y, 1, 1});
    fit(sums1_, {GL_TEXTURE_2D, GL_RGBA32F, size.x, size.y, 1, 1});
    fit(sums2_, {GL_TEXTURE_2D, GL_RGBA32F, size.x, size.y, 1, 1});
    fit(moments_, {GL_TEXTURE_2D, GL_RG32F, size.x, size.y, 1, 1});
    fit(lit_, {GL_TEXTURE_2D, GL_RGBA32F, lit.x, lit.y, 1, 1});
    return decision;
}

const gpu::Texture& BlockImpostorCache::keepSlices(const gpu::TextureDesc& desc) {
    fit(slices_, desc);
    lightKept_ = true;
    return slices_;
}

BlockImpostorAtlas BlockImpostorCache::importAtlas(gpu::FrameGraph& graph) const {
    return {.depths = graph.importTexture("block_impostor_depths", depths_),
            .sums1 = graph.importTexture("block_impostor_sums1", sums1_),
            .sums2 = graph.importTexture("block_impostor_sums2", sums2_),
            .moments = graph.importTexture("block_impostor_moments", moments_),
            .size = plan_.atlasSize};
}

}  // namespace nimbus::media
