#pragma once
// A setting declared once: its key, help text, type, valid range or words, its default, and the
// media modes and quality tiers in which it acts. Parsing (Settings::read), `sandbox settings`,
// the validation messages, the scene schema and the editor's widgets all follow from it.
//
// A module binds the specs it declares to the fields of its own typed settings struct with
// SettingField: readFields() starts from the struct the quality tier gives and applies every key
// that a user set, in declaration order.
//
// Does not: store values (Settings does), or know any module's keys.
#include <cstdint>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

namespace nimbus {

enum class SettingType : std::uint8_t {
    Boolean,  // on/off (a scene may write true/false)
    Integer,  // a whole number in [min, max], or one of `words`
    Number,   // a finite number in [min, max], or one of `words`
    Choice,   // one of `words`
};

// Quality tiers as bits, for SettingSpec::tiers (quality_tier.h names them).
inline constexpr unsigned kTierExact = 1u, kTierBalanced = 2u, kTierFast = 4u;
inline constexpr unsigned kEveryTier = kTierExact | kTierBalanced | kTierFast;

struct SettingSpec {
    std::string key;
    std::string help;                 // what it does, in one line; range, words and default are added
    SettingType type = SettingType::Boolean;
    double min = 0.0, max = 0.0;      // Integer, Number: the valid range, inclusive
    std::vector<std::string> words;   // Choice: its values; Integer, Number: words also accepted ("auto")
    std::string defaultValue;         // what it is when nobody sets it, as a user reads it
    std::vector<std::string> modes;   // the media modes it acts in; empty: every mode
    // The tiers it acts in with their own values of the other keys (kTier* bits); 0: every tier.
    // specsOf() derives it from SettingField::acts where a field has one.
    unsigned tiers = 0;
    // Where it acts only while other keys allow: that condition as a user reads it, e.g.
    // "with lighting=fragment". Empty: wherever `modes` says.
    std::string actsWhen;
    // What a scene must hold for its effect to show at all, e.g. "a point or spot light inside
    // the medium", kShowsWithMovingCamera or kShowsWithMovingMedium; empty: any scene with a medium (and meshes, for the
    // mesh keys).
    std::string showsWith;
};

// The showsWith of a key whose effect shows only in a frame after the camera moved (a cache).
inline constexpr char kShowsWithMovingCamera[] = "a camera that moves between frames";
// The showsWith of a key whose effect shows only in a frame after the medium moved (a warm start).
inline constexpr char kShowsWithMovingMedium[] = "a medium that moves between frames";

// A value read against its spec: `word` is set (with its index) when the value is one of the
// spec's words, else the typed field of the spec's type.
struct SettingValue {
    std::string word;
    int wordIndex = -1;
    bool boolean = false;
    long long integer = 0;
    double number = 0.0;
    bool isWord(const char* w) const { return word == w; }
};

// One line for `sandbox settings` and --help texts: the help, then the type with its range or
// words, the default, and where it acts.
std::string describeSetting(const SettingSpec& spec);
// "1..4096", "on or off", "fast, balanced or exact": what the spec accepts.
std::string acceptedValues(const SettingSpec& spec);
// Whether the spec acts in `mode` (a mode name) and `tierBit`.
bool settingActsIn(const SettingSpec& spec, const std::string& mode, unsigned tierBit);

enum class QualityTier : unsigned char;  // quality_tier.h

// A spec bound to a field of the typed struct S: `apply` writes the read value into it.
template <class S>
struct SettingField {
    SettingSpec spec;
    void (*apply)(S&, const SettingValue&) = nullptr;
    // Whether it acts with S as read (the tier's values with every key set applied), for a key that
    // another key turns off; null: it acts wherever spec.modes says. A key set where it does not
    // act is refused (idleKeys), never silently ignored.
    bool (*acts)(const S&) = nullptr;
};

// Appliers for the common shapes, e.g. &setInteger<&BlocksSettings::blocks>.
template <auto Member, class S>
void setBoolean(S& s, const SettingValue& v) { s.*Member = v.boolean; }
// For a field whose zero means on (zero is the default): the key's "off" sets it.
template <auto Member, class S>
void setBooleanOff(S& s, const SettingValue& v) { s.*Member = !v.boolean; }
template <auto Member, class S>
void setInteger(S& s, const SettingValue& v) { s.*Member = static_cast<int>(v.integer); }
template <auto Member, class S>
void setNumber(S& s, const SettingValue& v) { s.*Member = static_cast<float>(v.number); }
// A number or the word "auto": a number clears Auto, "auto" sets it and keeps the number the tier gave.
template <auto Member, auto Auto, class S>
void setNumberOrAuto(S& s, const SettingValue& v) {
    s.*Auto = v.isWord("auto");
    if (!(s.*Auto)) s.*Member = static_cast<float>(v.number);
}
// The word's index as the member's enum: the spec's words must be in the enum's order.
template <auto Member, class S>
void setChoice(S& s, const SettingValue& v) {
    using Enum = std::remove_reference_t<decltype(s.*Member)>;
    s.*Member = static_cast<Enum>(v.wordIndex);
}

// The specs alone, for declaring them. Where a field has `acts` and S has a
// `static S forTier(QualityTier)`, its spec's tiers are those whose own values it acts with.
template <class S, std::size_t N>
std::vector<SettingSpec> specsOf(const SettingField<S> (&fields)[N]) {
    std::vector<SettingSpec> out;
    for (const SettingField<S>& f : fields) {
        SettingSpec spec = f.spec;
        if constexpr (requires(QualityTier t) { S::forTier(t); }) {
            if (f.acts != nullptr) {
                spec.tiers = 0;
                for (unsigned t = 0; t < 3; ++t)
                    if (f.acts(S::forTier(static_cast<QualityTier>(t)))) spec.tiers |= 1u << t;
            }
        }
        out.push_back(spec);
    }
    return out;
}

// The keys of `fields` whose `acts` says they do not act with `resolved` (whether or not set).
template <class S, std::size_t N>
std::vector<std::string> idleKeys(const SettingField<S> (&fields)[N], const S& resolved) {
    std::vector<std::string> out;
    for (const SettingField<S>& f : fields)
        if (f.acts != nullptr && !f.acts(resolved)) out.push_back(f.spec.key);
    return out;
}

}  // namespace nimbus
