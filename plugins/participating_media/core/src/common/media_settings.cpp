// The settings every mode shares, declared once, and the reading of MediaRenderSettings.
#include "nimbus/media/media_settings.h"

#include <algorithm>

#include "nimbus/media/technique.h"

namespace nimbus::media {
namespace {

// Where media_scale=auto keeps full resolution (small billboards, thin cover) the upsampling keys
// change nothing: their effect needs a frame whose media target is reduced.
constexpr char kShowsWithReducedTarget[] = "a reduced media target (media_scale below 1, or auto where the billboards keep 8 texels at 1/2)";

// A slice count or detail set explicitly holds near meshes too (MediaRenderSettings::slicesNearMeshes).
void setSlices(MediaRenderSettings& s, const SettingValue& v) {
    s.slices = static_cast<int>(v.integer);
    s.slicesNearMeshes = 0;
}

// auto puts slice_detail texels (3 unless the tier or slice_detail says) across the median radius.
void setSliceResolution(MediaRenderSettings& s, const SettingValue& v) {
    if (v.isWord("auto")) {
        s.sliceResolution = 0;
        if (!(s.sliceTexelsPerRadius > 0.0f)) s.sliceTexelsPerRadius = 3.0f;
        return;
    }
    s.sliceResolution = static_cast<int>(v.integer);
    s.sliceTexelsPerRadius = s.sliceTexelsPerRadiusNearMeshes = 0.0f;
}

void setSliceDetail(MediaRenderSettings& s, const SettingValue& v) {
    if (!(s.sliceTexelsPerRadius > 0.0f)) return;
    s.sliceTexelsPerRadius = static_cast<float>(v.number);
    s.sliceTexelsPerRadiusNearMeshes = 0.0f;
}

bool sliceResolutionAuto(const MediaRenderSettings& s) { return s.sliceTexelsPerRadius > 0.0f; }
// The upsampler runs only where the media pass is smaller than the frame.

bool edgesRedrawn(const MediaRenderSettings& s) { return offscreenMedia(s) && !s.upsampleOnly; }

enum class Acts { Everywhere, LitBySlices, SliceDeposit, SliceCrop, MultipleScattering, Edges };

struct SharedField {
    SettingField<MediaRenderSettings> field;
    Acts acts;
};

// In the order they apply: slice_resolution before slice_detail.
const SharedField kSharedFields[] = {
    {{{.key = "slices", .help = "light slices per light view", .type = SettingType::Integer, .min = 4, .max = 32,
       .defaultValue = "chosen from the medium (fast: 16; blocks in fast where a mesh reaches into the medium: 32)"},
      &setSlices},
     Acts::LitBySlices},
    {{{.key = "slice_resolution",
       .help = "texels per side of a light slice; auto chooses it from the particles' size as the light sees them (slice_detail)",
       .type = SettingType::Integer,
       .min = 16,
       .max = 4096,
       .words = {"auto"},
       .defaultValue = "256 (balanced and fast: auto)"},
      &setSliceResolution},
     Acts::LitBySlices},
    {{{.key = "slice_detail", .help = "slice texels across the median particle's radius",
       .type = SettingType::Number, .min = 0.25, .max = 16.0,
       .defaultValue = "3 (balanced: 4, fast: 2; where a mesh reaches into the medium, particles in balanced: 6, blocks in fast: 4)",
       .actsWhen = "with slice_resolution=auto"},
      &setSliceDetail, &sliceResolutionAuto},
     Acts::LitBySlices},
    {{{.key = "slice_crop",
       .help = "where a mesh reaches into the medium, a second, finer light-slice view of each directional light over the "
               "meshes' overlap with it, read there (off: the whole view's slices everywhere)",
       .type = SettingType::Boolean, .defaultValue = "off",
       .actsWhen = "with slice_resolution=auto and a mesh reaching into the medium"},
      &setBoolean<&MediaRenderSettings::sliceCrop>, &sliceResolutionAuto},
     Acts::SliceCrop},
    {{{.key = "slice_deposit",
       .help = "light slices drawn as one float per particle and slab, then summed; auto: on unless a point or spot light's "
               "views are among them",
       .type = SettingType::Choice,
       .words = {"off", "on", "auto"},
       .defaultValue = "off (balanced and fast: auto)"},
      &setChoice<&MediaRenderSettings::sliceDeposit>},
     Acts::SliceDeposit},
    {{{.key = "media_scale",
       .help = "resolution of the media pass relative to the frame; auto: where the particles cover their own screen rect more "
               "than 2.5 times over, 1/4 to 1/2 keeping 8 texels across a typical billboard (1 where even 1/2 would not, or "
               "with a lamp among them that mixed_resolution does not draw again)",
       .type = SettingType::Number,
       .min = 0.0625,
       .max = 1.0,
       .words = {"auto"},
       .defaultValue = "1 (fast: auto)"},
      &setNumberOrAuto<&MediaRenderSettings::mediaScale, &MediaRenderSettings::mediaScaleAuto>},
     Acts::Everywhere},
    {{{.key = "upsample_threshold",
       .help = "offscreen media: relative depth difference the upsampling treats as an edge (where a mesh reaches into the "
               "medium, the modes of mixed_resolution draw the medium there again at full resolution)",
       .type = SettingType::Number, .min = 1e-4, .max = 10.0, .defaultValue = "0.2",
       .actsWhen = "with media_scale below 1 or auto", .showsWith = kShowsWithReducedTarget},
      &setNumber<&MediaRenderSettings::upsampleThreshold>, &offscreenMedia},
     Acts::Everywhere},
    {{{.key = "mixed_resolution",
       .help = "with media_scale below 1: draw the medium again at full resolution at the reduced image's edges where a mesh "
               "enters it and around a point light among the particles (off: upsampled there too, and a thin mesh shows a seam; "
               "faster; auto then keeps full resolution with a lamp among the particles)",
       .type = SettingType::Boolean, .defaultValue = "on",
       .actsWhen = "with media_scale below 1 or auto", .showsWith = kShowsWithReducedTarget},
      &setBooleanOff<&MediaRenderSettings::upsampleOnly>, &offscreenMedia},
     Acts::Edges},
    {{{.key = "mesh_cuts",
       .help = "with mixed_resolution: also draw the medium again at full resolution where a mesh's surface lies inside a "
               "particle and shows through the medium in front of it (off: only at the reduced image's depth edges; faster)",
       .type = SettingType::Boolean, .defaultValue = "on",
       .actsWhen = "with mixed_resolution on and media_scale below 1 or auto", .showsWith = kShowsWithReducedTarget},
      &setBooleanOff<&MediaRenderSettings::noMeshCuts>, &edgesRedrawn},
     Acts::Edges},
    {{{.key = "scattering_voxels", .help = "multiple scattering: voxels of the grid its scattered light diffuses on, along the medium's longest side "
               "(its boundary was fitted at 32: a finer grid is not more accurate, and can darken a dense cloud)",
       .type = SettingType::Integer, .min = 4, .max = 128, .defaultValue = std::to_string(kDefaultScatteringVoxels),
       .actsWhen = "in the multiple-scattering model"},
      &setInteger<&MediaRenderSettings::scatteringVoxels>},
     Acts::MultipleScattering},
    {{{.key = "scattering_sweeps", .help = "multiple scattering: most relaxation sweeps of its diffusion solve per frame (each frame starts from a coarser "
               "grid's solve; an unchanged medium and light keep the last frame's)",
       .type = SettingType::Integer, .min = 1, .max = 1024, .defaultValue = std::to_string(kDefaultScatteringSweeps),
       .actsWhen = "in the multiple-scattering model"},
      &setInteger<&MediaRenderSettings::scatteringSweeps>},
     Acts::MultipleScattering},
    {{{.key = "scattering_warm_sweeps",
       .help = "multiple scattering: a frame whose medium or lights moved a little (a light by at most 2 degrees or a voxel, "
               "its light by 10%) starts its diffusion solve from the last frame's answer and runs at most this many sweeps, so "
               "a moving plume pays a few sweeps a frame and its scattered light follows over frames; 16 takes about half the "
               "solve's time and errs up to 3% on a fast plume; a light that jumped or was switched, and the first frame after "
               "everything stops, are solved cold (0: cold every frame, so a frame's picture never depends on the ones before, "
               "as scrubbing and playing the editor's timeline rely on)",
       .type = SettingType::Integer, .min = 0, .max = 1024, .defaultValue = "0",
       .actsWhen = "in the multiple-scattering model", .showsWith = kShowsWithMovingMedium},
      &setInteger<&MediaRenderSettings::scatteringWarmSweeps>},
     Acts::MultipleScattering},
};

MediaRenderSettings sharedForTier(QualityTier tier) {
    MediaRenderSettings s;
    if (tier == QualityTier::Exact) return s;
    s.sliceDeposit = SliceDeposit::Auto;
    s.sliceTexelsPerRadius = tier == QualityTier::Fast ? 2.0f : 4.0f;
    if (tier == QualityTier::Fast) {
        s.slices = 16;
        s.mediaScaleAuto = true;
    }
    return s;
}

// The tier's shared settings as mode `entry` takes them.
MediaRenderSettings sharedForTier(QualityTier tier, const TechniqueEntry& entry) {
    MediaRenderSettings s = sharedForTier(tier);
    if (entry.sharedDefaults) entry.sharedDefaults(s, tier);
    return s;
}

SettingSpec modeSpec(const TechniqueTable& techniques) {
    SettingSpec spec{.key = "mode", .help = "how the medium is drawn:", .type = SettingType::Choice};
    for (const TechniqueEntry& e : techniques.entries()) {
        spec.help += std::string(spec.words.empty() ? " " : "; ") + e.name + ": " + e.help;
        spec.words.push_back(e.name);
    }
    if (!spec.words.empty()) spec.defaultValue = spec.words.front();
    return spec;
}

}  // namespace

MediaRenderSettings withDefaults(MediaRenderSettings s) {
    if (s.sliceResolution <= 0) s.sliceResolution = 256;
    if (s.mediaScale <= 0.0f) s.mediaScale = 1.0f;
    if (s.upsampleThreshold <= 0.0f) s.upsampleThreshold = 0.2f;
    if (s.scatteringVoxels <= 0) s.scatteringVoxels = kDefaultScatteringVoxels;
    if (s.scatteringSweeps <= 0) s.scatteringSweeps = kDefaultScatteringSweeps;
    return s;
}

MediaRenderSettings mediaSettingsForTier(QualityTier tier, const TechniqueTable& techniques, const std::string& mode) {
    const Settings none;
    const TechniqueEntry& entry = techniques.at(mode);
    MediaRenderSettings s = sharedForTier(tier, entry);
    s.mode = entry.name;
    s.technique = entry.read(none, tier);
    return s;
}

void declareMediaSettings(Settings& settings, const TechniqueTable& techniques) {
    settings.declare(qualityTierSpec());
    settings.declare(modeSpec(techniques));
    for (const SharedField& shared : kSharedFields) {
        SettingSpec spec = shared.field.spec;
        if (shared.field.acts != nullptr)
            for (unsigned t = 0; t < kQualityTierNames.size(); ++t)
                if (shared.field.acts(sharedForTier(static_cast<QualityTier>(t)))) spec.tiers |= 1u << t;
        for (const TechniqueEntry& e : techniques.entries())
            if ((shared.acts == Acts::LitBySlices && e.lightSlices) || (shared.acts == Acts::SliceDeposit && e.sliceDeposit) ||
                (shared.acts == Acts::SliceCrop && e.sliceCrops) ||
                (shared.acts == Acts::MultipleScattering && e.multipleScattering) || (shared.acts == Acts::Edges && e.edges))
                spec.modes.push_back(e.name);
        settings.declare(spec);
    }
    for (const TechniqueEntry& e : techniques.entries())
        for (const SettingSpec& spec : e.settings) settings.declare(spec);
}

MediaRenderSettings readMediaSettings(const Settings& settings, const TechniqueTable& techniques) {
    settings.validate();  // every key set is checked, whichever mode reads it
    const QualityTier tier = readQualityTier(settings);
    const TechniqueEntry& entry = techniques.at(settings.text("mode").value_or(""), settings.origin("mode"));
    MediaRenderSettings s = sharedForTier(tier, entry);
    for (const SharedField& shared : kSharedFields)
        if (const auto value = settings.read(shared.field.spec.key)) shared.field.apply(s, *value);
    s.mode = entry.name;
    s.technique = entry.read(settings, tier);
    return s;
}

namespace {

std::string joined(const std::vector<std::string>& words) {
    std::string out;
    for (std::size_t i = 0; i < words.size(); ++i) out += (i == 0 ? "" : i + 1 == words.size() ? " and " : ", ") + words[i];
    return out;
}

// "it acts only with lighting=fragment (the default in tier exact)"
std::string actsOnly(const SettingSpec& spec) {
    std::string out = "it acts only " + spec.actsWhen;
    std::vector<std::string> tiers;
    for (unsigned t = 0; t < kQualityTierNames.size(); ++t)
        if (spec.tiers & (1u << t)) tiers.emplace_back(kQualityTierNames[t]);
    if (!tiers.empty()) out += " (as in tier " + joined(tiers) + ")";
    return out;
}

}  // namespace

std::vector<IdleSetting> idleSettings(const Settings& settings, const TechniqueTable& techniques, bool multipleScattering) {
    const MediaRenderSettings s = readMediaSettings(settings, techniques);
    const TechniqueEntry& entry = techniques.at(s.mode);
    const std::string here = std::string("tier ") + qualityTierName(readQualityTier(settings)) + ", mode " + s.mode;
    std::vector<IdleSetting> out;
    auto idle = [&](const SettingSpec& spec, const std::string& why) {
        if (settings.has(spec.key)) out.push_back({spec.key, "has no effect in " + why});
    };
    std::vector<std::string> idleKeys;
    for (const SharedField& shared : kSharedFields)
        if (shared.field.acts != nullptr && !shared.field.acts(s)) idleKeys.push_back(shared.field.spec.key);
    if (entry.idle) {
        const std::vector<std::string> own = entry.idle(s.technique, s);
        idleKeys.insert(idleKeys.end(), own.begin(), own.end());
    }
    for (const SettingSpec& spec : settings.declarations()) {
        if (!spec.modes.empty() && std::find(spec.modes.begin(), spec.modes.end(), s.mode) == spec.modes.end())
            idle(spec, "mode " + s.mode + " (it acts in mode " + joined(spec.modes) + ")");
        else if (std::find(idleKeys.begin(), idleKeys.end(), spec.key) != idleKeys.end())
            idle(spec, here + ": " + actsOnly(spec));
    }
    if (!multipleScattering)
        for (const SharedField& shared : kSharedFields)
            if (shared.acts == Acts::MultipleScattering && entry.multipleScattering)
                idle(shared.field.spec, "the single-scattering model (it acts only in the multiple one)");
    return out;
}

}  // namespace nimbus::media
