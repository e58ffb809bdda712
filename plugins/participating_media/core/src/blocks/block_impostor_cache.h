#pragma once
// Blocks mode: what the `impostor_reuse` setting lets later frames read again, kept with everything
// it was rendered from:
//   - the light slices (the light views' impostors spread into slices), while nothing but the
//     camera changed: the light views do not depend on it;
//   - the camera's impostor atlas and its light, through a later view while the reuse rule holds
//     (planning/block_reuse.h) and the same blocks read their light from texels.
//
// Does not: reuse anything while the particles, the lights, the meshes' boxes, the ambient, the
// optical model, the target size or the settings differ in any way from the frame that rendered
// it; or when the host does not box every mesh (a mesh that moves unseen would leave its old
// shadow) or a volume is drawn (the technique does not ask then).
#include <cstdint>
#include <vector>

#include "blocks/block_impostor_pass.h"
#include "blocks/blocks_technique.h"
#include "nimbus/gpu/frame_graph.h"
#include "nimbus/media/graph_frame.h"
#include "nimbus/media/media_settings.h"
#include "nimbus/media/particle_set.h"
#include "planning/block_reuse.h"

namespace nimbus::media {

// Everything but the camera and the particles that the camera's atlas and its light are rendered
// from (the particles are compared where they stand, and copied only when they change).
struct ImpostorSources {
    std::vector<Light> lights;
    std::vector<OccluderBox> occluders;
    glm::vec3 ambient{0.0f};
    bool multiple = false;
    glm::ivec2 target{0};
    MediaRenderSettings shared;  // its `technique` is not compared: `own` is
    BlocksSettings own;
};
bool sameSources(const ImpostorSources& a, const ImpostorSources& b);

// What this frame reads again: the camera's atlas (Reused) and the light slices.
struct ReuseDecision {
    ReuseVerdict camera = ReuseVerdict::Changed;
    bool light = false;
};

class BlockImpostorCache {
public:
    // What this frame may read again. `builds`: per block, BlockCompositeBuild bits. When the
    // camera's atlas is reused, `plan` is rewritten to read it (reuseCameraTiles); otherwise this
    // frame renders it for `plan` into the kept textures. Light slices not reused are to be
    // rendered into keepSlices's.
    ReuseDecision decide(const ParticleSet& particles, ImpostorSources sources, const std::vector<std::uint8_t>& builds,
                         const BlockPartition& partition, const WorldView& view, const ImpostorReuseLimits& limits, BlockViewPlan& plan);
    void forget() { sourcesKept_ = cameraKept_ = lightKept_ = false; }

    // The kept atlas in `graph`: to be written this frame or read again.
    BlockImpostorAtlas importAtlas(gpu::FrameGraph& graph) const;
    // The kept light: RGBA32F at half the atlas's size (block_impostor_lighting_pass.h).
    const gpu::Texture& litTexture() const { return lit_; }
    // The kept light slices, to be written this frame with `desc` (later frames may read them) or read again.
    const gpu::Texture& keepSlices(const gpu::TextureDesc& desc);
    const gpu::Texture& slices() const { return slices_; }

private:
    bool sourcesKept_ = false, cameraKept_ = false, lightKept_ = false;
    ParticleSet particles_;
    ImpostorSources sources_;
    std::vector<std::uint8_t> builds_;
    BlockViewPlan plan_;
    WorldView view_;
    gpu::Texture depths_, sums1_, sums2_, moments_, lit_, slices_;
};

}  // namespace nimbus::media
