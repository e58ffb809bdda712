#pragma once
// Blocks mode: the impostor reuse rule. Blocks are "rendered once for the current viewing or
// lighting direction" (Umenhoffer and Szirmay-Kalos §1): a camera tile planned for an earlier view
// is read again through a later one while, for every block the later view sees,
//   - its direction from the eye has turned by at most `degrees` (parallax inside the block),
//   - its size on screen has grown or shrunk by at most `scale` (texels per pixel),
//   - the earlier tile holds all of it that the later view sees (a tile clipped at the screen's
//     edge holds nothing beyond it), and neither view's near plane cuts it.
// A pure turn of the camera about its eye keeps every block's direction: only coverage ends it.
//
// Does not: decide whether what the tiles were rendered from (particles, lights, settings) is
// unchanged; the caller keeps that (blocks/block_impostor_cache.h).
#include <vector>

#include <glm/glm.hpp>

#include "nimbus/media/block_partition.h"
#include "planning/block_view_plan.h"

namespace nimbus::media {

// A camera view in world space, as a tile set was planned for.
struct WorldView {
    glm::dvec3 origin{0.0};           // the eye; GPU coordinates are relative to it
    glm::dmat4 viewProjection{1.0};   // origin-relative world → clip
    glm::dvec3 forward{0.0, 0.0, -1.0};
    bool perspective = true;
    double znear = 0.0;
};

struct ImpostorReuseLimits {
    double degrees = 0.0;  // 0: never reuse
    double scale = 1.1;
};

// Reused, or the first reason found not to (Changed: the caller's sources differ, none is kept, or
// the tiles were planned for another partition or projection).
enum class ReuseVerdict { Reused, Changed, Turned, Scaled, Uncovered, NearPlane };
const char* reuseVerdictName(ReuseVerdict verdict);

// Whether `then`'s tiles (planned for `thenView`) may be read for `nowView`. When they may, `now`
// (this frame's plan of the same partition) is rewritten to read them: each visible block keeps
// its rectangle in the new view, takes its old atlas tile, a projective map from the new view's
// NDC to that tile's texels (GpuBlockTile::reproject) and the change of its distance from the eye
// as its depth offset. Otherwise `now` is left as it is, as it is for the very same view (whose
// plan is `then`'s: a still camera reads the kept atlas as the frame that rendered it did).
ReuseVerdict reuseCameraTiles(const BlockPartition& partition, const BlockViewPlan& then, const WorldView& thenView,
                              const WorldView& nowView, const ImpostorReuseLimits& limits, BlockViewPlan& now);

}  // namespace nimbus::media
