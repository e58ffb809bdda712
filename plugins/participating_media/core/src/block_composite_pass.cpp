// Blocks mode, camera side: the blocks composited back to front over their screen rectangles from
// the camera's impostor atlas (block_impostor_pass.cpp), shaders/media/block_composite.*.
#include "block_passes.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/gtc/matrix_access.hpp>

#include "nimbus/gpu/shader_program.h"
#include "nimbus/render/frame_data.h"
#include "nimbus/render/gpu_scene.h"

namespace nimbus::media {

inline constexpr GLuint kShadowDepthUnit = 4;
inline constexpr GLuint kImpostorDepthsUnit = 5;
inline constexpr GLuint kSeamMaskUnit = 9;
inline constexpr GLint kFirstRankLocation = 2;  // block_composite.vert uFirstRank
inline constexpr GLint kSeamPartLocation = 3;   // block_composite.frag uSeamPart
inline constexpr GLint kSeamCellLocation = 5;   // block_composite.frag uSeamCell

std::vector<MeshBox> meshInstanceBoxes(const render::FrameInput& input) {
    std::vector<MeshBox> boxes;
    if (input.gpuScene == nullptr) return boxes;
    boxes.reserve(input.instances.size());
    for (const render::MeshInstance& instance : input.instances) {
        const auto& [lo, hi] = input.gpuScene->localBounds(instance.mesh);
        if (lo.x > hi.x) continue;  // a mesh without triangles
        const glm::dvec3 localCentre = 0.5 * (glm::dvec3(lo) + glm::dvec3(hi)), localHalf = 0.5 * (glm::dvec3(hi) - glm::dvec3(lo));
        MeshBox box;
        box.centre = glm::dvec3(instance.world * glm::dvec4(localCentre, 1.0));
        const glm::dmat3 linear(instance.world);
        double length[3];
        for (int k = 0; k < 3; ++k) length[k] = glm::length(linear[k]);
        const bool orthogonal = std::abs(glm::dot(linear[0], linear[1])) <= 1e-9 * length[0] * length[1] &&
                                std::abs(glm::dot(linear[0], linear[2])) <= 1e-9 * length[0] * length[2] &&
                                std::abs(glm::dot(linear[1], linear[2])) <= 1e-9 * length[1] * length[2];
        if (orthogonal && length[0] > 0.0 && length[1] > 0.0 && length[2] > 0.0) {
            for (int k = 0; k < 3; ++k) {
                box.axis[k] = linear[k] / length[k];
                box.half[k] = localHalf[k] * length[k];
            }
        } else {
            for (int k = 0; k < 3; ++k) box.half[k] = glm::dot(glm::abs(glm::row(linear, k)), localHalf);  // axis-aligned around it
        }
        boxes.push_back(box);
    }
    return boxes;
}

std::vector<std::uint8_t> blocksNearMeshes(const BlockPartition& partition, const std::vector<MeshBox>& meshes) {
    std::vector<std::uint8_t> near(partition.blocks.size(), 0);
    // Only meshes whose axis-aligned hull meets the blocks' reach at all are tested block by block
    // (a level of many meshes around one cloud).
    glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
    for (const Block& block : partition.blocks) {
        const double reach = block.radius + block.meanParticleRadius;
        lo = glm::min(lo, block.centre - reach);
        hi = glm::max(hi, block.centre + reach);
    }
    std::vector<const MeshBox*> candidates;
    for (const MeshBox& box : meshes) {
        glm::dvec3 hull(0.0);
        for (int k = 0; k < 3; ++k) hull += glm::abs(box.axis[k]) * box.half[k];
        if (glm::all(glm::lessThanEqual(box.centre - hull, hi)) && glm::all(glm::greaterThanEqual(box.centre + hull, lo)))
            candidates.push_back(&box);
    }
    for (std::size_t b = 0; b < partition.blocks.size() && !candidates.empty(); ++b) {
        const Block& block = partition.blocks[b];
        const double reach = block.radius + block.meanParticleRadius;
        for (const MeshBox* candidate : candidates) {
            const MeshBox& box = *candidate;
            const glm::dvec3 d = block.centre - box.centre;
            double outside = 0.0;  // squared distance from the centre to the box
            for (int k = 0; k < 3; ++k) {
                const double excess = std::max(std::abs(glm::dot(d, box.axis[k])) - box.half[k], 0.0);
                outside += excess * excess;
            }
            if (outside <= reach * reach) {
                near[b] = 1;
                break;
            }
        }
    }
    return near;
}

namespace {

// The NDC rectangle (min xy, max zw) a box covers in `view`; the whole screen where it reaches
// behind the eye.
glm::dvec4 screenRectangle(const MeshBox& box, const render::View& view) {
    glm::dvec4 rect(std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                    -std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity());
    const glm::dmat4 viewProjection(view.viewProjection);
    for (int corner = 0; corner < 8; ++corner) {
        glm::dvec3 p = box.centre - view.origin;
        for (int k = 0; k < 3; ++k) p += box.axis[k] * ((corner >> k) & 1 ? box.half[k] : -box.half[k]);
        const glm::dvec4 clip = viewProjection * glm::dvec4(p, 1.0);
        if (!(clip.w > 1e-9)) return glm::dvec4(-1.0, -1.0, 1.0, 1.0);
        const glm::dvec2 ndc = glm::dvec2(clip) / clip.w;
        rect = glm::dvec4(glm::min(glm::dvec2(rect), ndc), glm::max(glm::dvec2(rect.z, rect.w), ndc));
    }
    return rect;
}

}  // namespace

std::vector<std::uint8_t> blocksShadedExactly(const BlockPartition& partition, const std::vector<MeshBox>& meshes,
                                              const BlockViewPlan& cameraPlan, const render::View& view) {
    std::vector<std::uint8_t> exact(partition.blocks.size(), 0);
    // One mesh at a time: the blocks near it, and whether it passes among the blocks at all.
    std::vector<glm::dvec4> rects;
    std::vector<double> farthest;  // a mesh box's farthest distance from the eye
    for (const MeshBox& box : meshes) {
        const std::vector<std::uint8_t> near = blocksNearMeshes(partition, {box});
        if (std::find(near.begin(), near.end(), std::uint8_t{1}) == near.end()) continue;
        for (std::size_t b = 0; b < exact.size(); ++b) exact[b] |= near[b];
        rects.push_back(screenRectangle(box, view));
        double hull = 0.0;
        for (int k = 0; k < 3; ++k) hull += box.half[k] * box.half[k];
        farthest.push_back(glm::length(box.centre - view.origin) + std::sqrt(hull));
    }
    for (std::size_t b = 0; b < partition.blocks.size() && !rects.empty(); ++b) {
        if (!(cameraPlan.tiles[b].atlas.z > 0.0f)) continue;  // not drawn (off the screen)
        const glm::vec4 rect = cameraPlan.tiles[b].rect;
        const Block& block = partition.blocks[b];
        const double nearest = glm::length(block.centre - view.origin) - block.radius;
        for (std::size_t m = 0; m < rects.size() && !exact[b]; ++m) {
            const bool overlaps = rect.x <= rects[m].z && rect.z >= rects[m].x && rect.y <= rects[m].w && rect.w >= rects[m].y;
            if (overlaps && nearest < farthest[m]) exact[b] = 1;
        }
    }
    return exact;
}

bool sliceViewResolves(const render::GpuLightView& v, const glm::dvec3& centre, double radius, double sigma) {
    const double spacing = (static_cast<double>(v.params.z) - v.params.y) / std::max(static_cast<double>(v.params.w), 1.0);
    const double depth = -(glm::dmat4(v.view) * glm::dvec4(centre, 1.0)).z;
    const double texel = v.params2.y * (v.params.x > 0.5f ? std::max(depth, 0.0) : 1.0);
    return spacing <= 2.0 * radius && texel <= radius && sigma * std::max(spacing, texel) <= 2.0;
}

std::vector<std::uint8_t> blocksOfUnresolvedParticles(const BlockPartition& partition, const ParticleSet& particles,
                                                       const std::vector<render::GpuLightView>& views, const glm::dvec3& origin) {
    std::vector<std::uint8_t> unresolved(partition.blocks.size(), 0);
    for (std::size_t b = 0; b < partition.blocks.size(); ++b) {
        const Block& block = partition.blocks[b];
        if (block.count == 0 || block.count > kMaxOwnShadedBlockParticles) continue;
        const glm::dvec3 centre = block.centre - origin;
        for (std::uint32_t k = block.first; k < block.first + block.count && !unresolved[b]; ++k) {
            const std::uint32_t i = partition.order[k];
            for (const render::GpuLightView& v : views) {
                if (!sliceViewResolves(v, centre, particles.radius[i], particles.sigma[i])) {
                    unresolved[b] = 1;
                    break;
                }
            }
        }
    }
    return unresolved;
}

BlockCompositePass::BlockCompositePass() { programs(kBlockPlain); }

LocalLightPrograms& BlockCompositePass::programs(std::uint8_t build) {
    std::unique_ptr<LocalLightPrograms>& programs = programs_[build & 7];
    if (!programs) programs = std::make_unique<LocalLightPrograms>(blockCompositeDesc(build));
    return *programs;
}

gpu::ProgramDesc blockCompositeDesc(std::uint8_t build) {
    gpu::ProgramDesc desc{.vertex = "media/block_composite.vert", .fragment = "media/block_composite.frag"};
    if (build & kBlockExactCut) desc.defines.push_back("BLOCK_EXACT_CUT");
    if (build & kBlockOwnParticles) desc.defines.push_back("BLOCK_OWN_PARTICLES");
    if (build & kBlockExactShading) desc.defines.push_back("BLOCK_EXACT_SHADING");
    return desc;
}

render::ResourceHandle BlockCompositePass::add(render::FrameGraph& graph, render::FrameContext& context, const BlockImpostorAtlas& made,
                                               const std::vector<std::uint32_t>& backToFront, const std::vector<std::uint8_t>& builds,
                                               bool seamOnly, const BlockGpuBuffers& blocks, const ParticleGpuBuffer& particles,
                                               const MediaTarget& target) {
    struct Composite {
        render::ResourceHandle media, depth, shadowMap, slices, depths, sums1, sums2, moments, seamMask, seamStencil;
    };
    const int w = target.size.x, h = target.size.y;
    // Runs of consecutive ranks that want the same build, drawn in order.
    struct Run {
        BlockRankRun ranks;
        std::uint8_t build;
    };
    std::vector<Run> runs;
    for (std::size_t r = 0; r < backToFront.size(); ++r) {
        const std::uint8_t build = builds[backToFront[r]] & 7;
        if (runs.empty() || build != runs.back().build) runs.push_back({{static_cast<GLint>(r), 0}, build});
        ++runs.back().ranks.count;
    }
    // With seamOnly, the mask says where the blocks a mesh comes near are cut, and an exactly shaded
    // run is drawn twice: smoothly off the seam, then exactly near it (the mask pass's stencil says
    // which texels each draw shades). At each texel one of the two draws writes every block of the
    // run, so the back-to-front order holds.
    std::vector<BlockRankRun> cutRuns;
    bool seamRuns = false;
    for (const Run& run : runs) {
        if (run.build & kBlockExactCut) cutRuns.push_back(run.ranks);
        seamRuns = seamRuns || (run.build & kBlockExactShading);
    }
    BlockSeamMaskPass::Output seam;
    const int seamCell = seamMaskCell(target.size);
    if (seamOnly && seamRuns && !cutRuns.empty()) {
        if (!seamMask_) seamMask_ = std::make_unique<BlockSeamMaskPass>();
        seam = seamMask_->add(graph, context, std::move(cutRuns), blocks, made.depths, target, seamCell);
    }
    // Each draw: its ranks, program and seam part (block_composite.frag uSeamPart).
    struct Draw {
        BlockRankRun ranks;
        const gpu::Program* program;
        GLint seamPart;
    };
    std::vector<Draw> draws;
    for (const Run& run : runs) {
        const auto smooth = static_cast<std::uint8_t>(run.build & ~kBlockExactShading);
        if (!seamOnly || !(run.build & kBlockExactShading)) {
            draws.push_back({run.ranks, &programs(run.build).forLights(context.input.lights), 0});
        } else if (seam.mask.valid()) {
            draws.push_back({run.ranks, &programs(smooth).forLights(context.input.lights), 1});
            draws.push_back({run.ranks, &programs(run.build).forLights(context.input.lights), 2});
        } else {  // no block a mesh comes near: no seam
            draws.push_back({run.ranks, &programs(smooth).forLights(context.input.lights), 0});
        }
    }
    const auto& data = graph.addPass<Composite>(
        "media_blocks",
        [&](render::PassBuilder& builder, Composite& d) {
            d.media = builder.create(target.name, {GL_TEXTURE_2D, GL_RGBA32F, w, h, 1, 1});
            d.depth = builder.read(context.sceneDepth);
            if (context.shadowMap.valid()) d.shadowMap = builder.read(context.shadowMap);
            if (context.transmittanceSlices.valid()) d.slices = builder.read(context.transmittanceSlices);
            d.depths = builder.read(made.depths);
            d.sums1 = builder.read(made.sums1);
            d.sums2 = builder.read(made.sums2);
            d.moments = builder.read(made.moments);
            if (seam.mask.valid()) {
                d.seamMask = builder.read(seam.mask);
                d.seamStencil = builder.read(seam.stencil);
            }
        },
        [this, draws, &context, &blocks, &particles, w, h, seamCell, scale = target.fullResScale](const render::PassResources& r,
                                                                                                 const Composite& d) {
            gpu::Framebuffer fbo = gpu::createFramebuffer();
            glNamedFramebufferTexture(fbo.id(), GL_COLOR_ATTACHMENT0, r.id(d.media), 0);
            glNamedFramebufferDrawBuffer(fbo.id(), GL_COLOR_ATTACHMENT0);
            // Read only: a seam run's draws test it (stencil 1: near the seam), write nothing to it.
            if (d.seamStencil.valid()) glNamedFramebufferTexture(fbo.id(), GL_DEPTH_STENCIL_ATTACHMENT, r.id(d.seamStencil), 0);
            glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
            glViewport(0, 0, w, h);
            const float clear[4] = {0.0f, 0.0f, 0.0f, 1.0f};
            glClearNamedFramebufferfv(fbo.id(), GL_COLOR, 0, clear);
            for (const Draw& draw : draws) {
                glProgramUniform2f(draw.program->id(), 1, scale.x, scale.y);
                glProgramUniform1i(draw.program->id(), kSeamCellLocation, seamCell);
            }
            context.frameData->bind();
            blocks.bind(0);
            particles.bindParticles();  // the listed particles around each lamp (lamp_neighbourhood.glsl)
            particles.bindLampNeighbourhoods();
            glBindTextureUnit(render::kSceneDepthUnit, r.id(d.depth));
            if (d.shadowMap.valid()) glBindTextureUnit(kShadowDepthUnit, r.id(d.shadowMap));
            if (d.slices.valid()) glBindTextureUnit(render::kTransmittanceUnit, r.id(d.slices));
            glBindTextureUnit(kImpostorDepthsUnit, r.id(d.depths));
            glBindTextureUnit(kImpostorDepthsUnit + 1, r.id(d.sums1));
            glBindTextureUnit(kImpostorDepthsUnit + 2, r.id(d.sums2));
            glBindTextureUnit(kImpostorDepthsUnit + 3, r.id(d.moments));
            if (d.seamMask.valid()) glBindTextureUnit(kSeamMaskUnit, r.id(d.seamMask));
            glDisable(GL_DEPTH_TEST);
            glDisable(GL_CULL_FACE);
            glEnable(GL_BLEND);
            glBlendEquation(GL_FUNC_ADD);
            glBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE_MINUS_SRC_ALPHA);
            glBindVertexArray(vertexArray_.id());
            for (const Draw& draw : draws) {
                const GLuint program = draw.program->id();
                glUseProgram(program);
                glProgramUniform1i(program, kFirstRankLocation, draw.ranks.first);
                glProgramUniform1i(program, kSeamPartLocation, draw.seamPart);
                if (draw.seamPart != 0) {
                    glEnable(GL_STENCIL_TEST);
                    glStencilFunc(GL_EQUAL, draw.seamPart == 2 ? 1 : 0, 0xFF);
                    glStencilMask(0x00);
                } else {
                    glDisable(GL_STENCIL_TEST);
                }
                glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, draw.ranks.count);
            }
            glDisable(GL_STENCIL_TEST);
            glStencilMask(0xFF);
            glBindVertexArray(0);
            glDisable(GL_BLEND);
            glBindFramebuffer(GL_FRAMEBUFFER, 0);
        });
    return data.media;
}

}  // namespace nimbus::media
