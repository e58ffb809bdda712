#pragma once
// The quality tiers (`quality`, `sandbox render --quality`): each module gives its typed settings
// for a tier (for example the media plugin's lighting, the renderer's shadow filtering), and a
// setting given explicitly wins over its tier's value. `exact` evaluates every correction and is
// the library's default; `balanced` and `fast` trade error for speed (docs/PERFORMANCE.md).
#include <array>
#include <string>

#include "nimbus/base/setting_spec.h"

namespace nimbus {

class Settings;

// In the order of SettingSpec words for `quality`: exact is zero, so a value-initialised tier is exact.
enum class QualityTier : unsigned char { Exact, Balanced, Fast };
inline constexpr std::array<const char*, 3> kQualityTierNames = {"exact", "balanced", "fast"};

inline const char* qualityTierName(QualityTier tier) { return kQualityTierNames[static_cast<std::size_t>(tier)]; }
inline unsigned qualityTierBit(QualityTier tier) { return 1u << static_cast<unsigned>(tier); }

// The `quality` setting's declaration (the render and media plugins both declare it).
SettingSpec qualityTierSpec();
// The tier `settings` select (exact when unset or when nothing declared `quality`); InputError
// naming where a bad value came from.
QualityTier readQualityTier(const Settings& settings);

}  // namespace nimbus
