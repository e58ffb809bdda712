#pragma once
// `sheets` (image-aligned sheet-buffer splatting: Mueller and Crawfis, and the sheet-buffer
// splatting paper): the medium cut by planes parallel to the image; each particle's kernel enters
// every sheet it crosses as a slab pre-integrated in the kernel table, the slabs of one sheet are
// summed (no order among them to flip) and the sheets composited back to front. Lit by the
// per-particle lighting pass through the light slices, as the fast tiers of `particles` are.
#include "nimbus/base/quality_tier.h"
#include "nimbus/media/technique.h"

namespace nimbus::media {

struct SheetsSettings {
    float spacing = 0.0f;           // metres between sheets; 0: spacingPerRadius × the median radius
    float spacingPerRadius = 0.25f;  // the tier's spacing in radii (the paper uses 1/2)
    bool exactLighting = true;      // each of the lighting pass's rays shaded as a fragment (off: fitted)

    static SheetsSettings forTier(QualityTier tier);
};

TechniqueEntry sheetsTechnique();

}  // namespace nimbus::media
