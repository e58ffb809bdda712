#pragma once
// `raymarch` (Schpok et al., and Jendersie's ray-marched clouds): the particles voxelised on the CPU each
// frame and the grid ray-marched per pixel of the media target, lit through the light slices.
#include "nimbus/base/quality_tier.h"
#include "nimbus/media/technique.h"

namespace nimbus::media {

inline constexpr int kDefaultRaymarchSteps = 128;

struct RaymarchSettings {
    int voxels = 0;         // voxels along the grid's longest side; 0: from the particle size (voxel_grid.h)
    int raymarchSteps = 0;  // most samples per ray; 0: kDefaultRaymarchSteps

    static RaymarchSettings forTier(QualityTier) { return {}; }
};

TechniqueEntry raymarchTechnique();

}  // namespace nimbus::media
