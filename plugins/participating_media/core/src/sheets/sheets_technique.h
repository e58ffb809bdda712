#pragma once
// `sheets` (image-aligned sheet-buffer splatting: Mueller and Crawfis, and the sheet-buffer
// splatting paper): the medium cut by planes parallel to the image; each particle's kernel enters
// every sheet it crosses as a slab pre-integrated in the kernel table, the slabs of one sheet are
// summed (no order among them to flip) and the sheets composited back to front. Lit through the
// light slices: per fragment over each slab (the exact tier), or by the per-particle lighting pass
// of `particles`' cheaper tiers.
#include <cstdint>

#include "nimbus/base/quality_tier.h"
#include "nimbus/media/technique.h"

namespace nimbus::media {

// Where the slabs are lit, in the order of the sheet_lighting words (as ParticleLighting).
enum class SheetLighting : std::uint8_t {
    Fragment,       // per fragment over each slab, as particles.frag shades a pixel: the exact tier
    Particle,       // the per-particle lighting pass's fit across the billboard
    ParticleExact,  // as Particle, each of its rays shaded as a fragment
};

struct SheetsSettings {
    float spacing = 0.0f;           // metres between sheets; 0: spacingPerRadius × the median radius
    float spacingPerRadius = 0.5f;  // the tier's spacing in radii (the paper's R/2)
    SheetLighting lighting = SheetLighting::Fragment;

    static SheetsSettings forTier(QualityTier tier);
};

TechniqueEntry sheetsTechnique();

}  // namespace nimbus::media
