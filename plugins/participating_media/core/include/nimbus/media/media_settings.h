#pragma once
// The media renderer's settings: what every mode shares (the light slices, the media target), the
// mode's name and the mode's own typed settings. Each key is declared once (setting_spec.h): the
// shared ones here, each mode's in its technique (technique.h). A host may fill the struct
// directly ({} is the exact tier with every default) or read it from string settings.
//
// Does not: name any mode. The technique table does.
#include <any>
#include <cstdint>
#include <string>
#include <vector>

#include "nimbus/base/quality_tier.h"
#include "nimbus/base/settings.h"

namespace nimbus::media {

class TechniqueTable;

enum class SliceDeposit : std::uint8_t { Off, On, Auto };  // in the order of the slice_deposit words

// Zero values take the defaults noted (withDefaults).
struct MediaRenderSettings {
    std::string mode;          // a technique's name (TechniqueTable); empty: the table's first
    int slices = 0;            // per light view; 0: chosen from the medium (see slice_plan.h), else 4..32
    int sliceResolution = 0;   // texels per side of a slice; 0: 256
    float sliceTexelsPerRadius = 0.0f;  // > 0: the resolution instead puts this many texels across the
                                        // median particle's radius (slice_plan.h sliceResolutionFor)
    // Where a mesh reaches into the medium (a mesh's box meets the particles' bounds): the slices and
    // slice detail instead of the two above; 0: the same. A mode's tier may set them (blocks in
    // fast: there the light a mesh cuts in the medium is its seam's error); `slices`, `slice_detail`
    // or a fixed `slice_resolution` set explicitly clears its own.
    int slicesNearMeshes = 0;
    float sliceTexelsPerRadiusNearMeshes = 0.0f;
    // Slices as one float per particle and slab, then a running sum (the same values as the exact
    // pass within float rounding); auto: unless a lamp's views are among them.
    SliceDeposit sliceDeposit = SliceDeposit::Off;
    // slice_crop=on: a second, finer slice view of each directional light over where meshes reach
    // into the medium (planning/slice_crop.h), with an automatic slice resolution. Off in every
    // tier: where the meshes span the medium's depth along the light (cumulus_aircraft) it draws
    // most particles again, and costs the fast frame 40–55% (docs/design-notes.md).
    bool sliceCrop = false;
    float mediaScale = 0.0f;   // resolution of the media pass relative to the frame (1, 0.5, 0.25); 0: 1
    bool mediaScaleAuto = false;  // automaticMediaScale (media_renderer.h)
    float upsampleThreshold = 0.0f;  // relative depth difference the upsampler treats as an edge; 0: 0.2
    // mixed_resolution=off: a reduced image is upsampled everywhere, its edges where a mesh enters
    // the medium not drawn again at full resolution (MediaTechnique::addEdges).
    bool upsampleOnly = false;
    // mesh_cuts=off: of the pixels where a mesh's surface lies inside a particle, only the depth
    // edges are drawn again (upsample/media_seam_marks_pass.h).
    bool noMeshCuts = false;
    // The multiple-scattering model's grid (common/environment_grid.h), for frames of the multiple
    // model; zero: the defaults below.
    int scatteringVoxels = 0;  // voxels along the medium's longest side
    int scatteringSweeps = 0;  // most sweeps of the diffusion solve per frame
    // A frame whose medium or lights changed starts its solve from the last frame's answer and runs
    // at most this many sweeps; 0: from scratch (a coarser grid's solve) every time, so a frame's
    // picture never depends on the frames before it.
    int scatteringWarmSweeps = 0;
    // The technique's own settings (TechniqueEntry::read gives them); empty: its defaults.
    std::any technique;
};

// Whether the medium is drawn at a reduced resolution (media_scale below 1, or auto) and upsampled.
inline bool offscreenMedia(const MediaRenderSettings& s) { return s.mediaScaleAuto || (s.mediaScale > 0.0f && s.mediaScale < 1.0f); }

inline constexpr int kDefaultScatteringVoxels = 32;
inline constexpr int kDefaultScatteringSweeps = 64;

// The settings with each zero field that stands for a value given it (sliceResolution 256,
// mediaScale 1, upsampleThreshold 0.2, the scattering defaults); where zero means "choose"
// (slices) it stays.
// MediaRenderer::prepare applies it, so a host may pass {} or only what it sets.
MediaRenderSettings withDefaults(MediaRenderSettings settings);

// What `tier` picks for `mode` (empty: the table's first), the mode's own settings included: the
// settings a Settings with only `quality` set reads as.
MediaRenderSettings mediaSettingsForTier(QualityTier tier, const TechniqueTable& techniques, const std::string& mode = "");

// Declares `quality`, `mode` (its words from the table), the shared keys and every technique's.
void declareMediaSettings(Settings& settings, const TechniqueTable& techniques);
// The settings `settings` fix: the tier's values with every key set applied, the mode's own
// settings included. InputError naming where a bad value came from.
MediaRenderSettings readMediaSettings(const Settings& settings, const TechniqueTable& techniques);

// A key set where it has no effect, with why: "has no effect in mode billboards (it acts in mode
// particles, blocks and raymarch)", "has no effect in tier balanced, mode particles: it acts only
// with lighting=fragment (as in tier exact)".
struct IdleSetting {
    std::string key;
    std::string why;
};
// Every key set in `settings` that would not act on a frame they read as: one a mode does not
// draw, one the tier's or another key's value turns off (SettingField::acts), one of the
// multiple-scattering model's in a single-scattering scene. From the declarations alone, so a
// new key is covered when it is declared. InputError as readMediaSettings for a bad value.
std::vector<IdleSetting> idleSettings(const Settings& settings, const TechniqueTable& techniques, bool multipleScattering);

// A technique's own settings from MediaRenderSettings::technique, or S{} where it holds none.
template <class S>
S techniqueSettings(const MediaRenderSettings& settings) {
    if (!settings.technique.has_value()) return S{};
    return std::any_cast<const S&>(settings.technique);
}

}  // namespace nimbus::media
