#include "nimbus/base/settings.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "nimbus/base/error.h"
#include "nimbus/base/quality_tier.h"

namespace nimbus {
namespace {

bool sameShape(const SettingSpec& a, const SettingSpec& b) {
    return a.type == b.type && a.min == b.min && a.max == b.max && a.words == b.words;
}

std::string joinWords(const std::vector<std::string>& words, const char* last) {
    std::string out;
    for (std::size_t i = 0; i < words.size(); ++i)
        out += (i == 0 ? "" : i + 1 == words.size() ? last : ", ") + words[i];
    return out;
}

int wordIndex(const SettingSpec& spec, const std::string& value) {
    const auto it = std::find(spec.words.begin(), spec.words.end(), value);
    return it == spec.words.end() ? -1 : static_cast<int>(it - spec.words.begin());
}

// "where: key: 'v' is not X (expected ...)"; the key is left out where `where` already ends with
// it (a scene's render.KEY field).
[[noreturn]] void refuse(const std::string& where, const SettingSpec& spec, const std::string& problem) {
    const bool named = where.size() > spec.key.size() && where.compare(where.size() - spec.key.size(), spec.key.size(), spec.key) == 0 &&
                       where[where.size() - spec.key.size() - 1] == '.';
    throwInputError(where, named ? "" : spec.key, "", problem + " (expected " + acceptedValues(spec) + ")");
}

SettingValue parseValue(const SettingSpec& spec, const std::string& v, const std::string& where) {
    SettingValue out;
    if (const int w = wordIndex(spec, v); w >= 0) {
        out.word = v;
        out.wordIndex = w;
        return out;
    }
    switch (spec.type) {
        case SettingType::Boolean:
            if (v == "on" || v == "true") out.boolean = true;
            else if (v == "off" || v == "false") out.boolean = false;
            else refuse(where, spec, "'" + typedText(v) + "' is not on or off");
            return out;
        case SettingType::Choice:
            refuse(where, spec, "'" + typedText(v) + "' is not one of its values");
        case SettingType::Integer: {
            const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), out.integer);
            if (ec == std::errc::result_out_of_range && end == v.data() + v.size())
                refuse(where, spec, typedText(v) + " is outside its range");
            if (ec != std::errc() || end != v.data() + v.size()) refuse(where, spec, "'" + typedText(v) + "' is not a whole number");
            if (static_cast<double>(out.integer) < spec.min || static_cast<double>(out.integer) > spec.max)
                refuse(where, spec, typedText(v) + " is outside its range");
            out.number = static_cast<double>(out.integer);
            return out;
        }
        case SettingType::Number: {
            const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), out.number);
            if (ec != std::errc() || end != v.data() + v.size() || !std::isfinite(out.number))
                refuse(where, spec, "'" + typedText(v) + "' is not a finite number");
            if (out.number < spec.min || out.number > spec.max) refuse(where, spec, typedText(v) + " is outside its range");
            return out;
        }
    }
    refuse(where, spec, "unreadable");
}

}  // namespace

std::string formatSettingNumber(double value) {
    char text[32];
    if (value == std::floor(value) && std::abs(value) < 1e15) std::snprintf(text, sizeof text, "%.0f", value);
    else std::snprintf(text, sizeof text, "%.6g", value);
    return text;
}

std::string acceptedValues(const SettingSpec& spec) {
    std::string range;
    switch (spec.type) {
        case SettingType::Boolean: range = "on or off"; break;
        case SettingType::Choice: return joinWords(spec.words, " or ");
        case SettingType::Integer: range = "a whole number " + formatSettingNumber(spec.min) + ".." + formatSettingNumber(spec.max); break;
        case SettingType::Number: range = "a number " + formatSettingNumber(spec.min) + ".." + formatSettingNumber(spec.max); break;
    }
    return spec.words.empty() ? range : range + " or " + joinWords(spec.words, " or ");
}

bool settingActsIn(const SettingSpec& spec, const std::string& mode, unsigned tierBit) {
    const bool inMode = spec.modes.empty() || std::find(spec.modes.begin(), spec.modes.end(), mode) != spec.modes.end();
    return inMode && (spec.tiers == 0 || (spec.tiers & tierBit) != 0);
}

std::string describeSetting(const SettingSpec& spec) {
    std::string out = spec.help + "; " + acceptedValues(spec);
    if (!spec.defaultValue.empty()) out += "; default " + spec.defaultValue;
    if (!spec.modes.empty()) out += "; in mode " + joinWords(spec.modes, " and ");
    if (spec.tiers != 0 && spec.tiers != kEveryTier) {
        std::vector<std::string> tiers;
        for (std::size_t t = 0; t < kQualityTierNames.size(); ++t)
            if (spec.tiers & (1u << t)) tiers.emplace_back(kQualityTierNames[t]);
        out += std::string(spec.modes.empty() ? "; in" : ",") + " tier " + joinWords(tiers, " and ");
    }
    if (!spec.actsWhen.empty()) out += "; acts only " + spec.actsWhen;
    if (!spec.showsWith.empty()) out += "; shows only with " + spec.showsWith;
    return out;
}

void Settings::declare(const SettingSpec& spec) {
    if (const SettingSpec* existing = find(spec.key)) {
        if (!sameShape(*existing, spec)) throw std::logic_error("setting '" + spec.key + "' declared twice with different specs");
        return;
    }
    specs_.push_back(spec);
}

const SettingSpec* Settings::find(const std::string& key) const {
    const auto it = std::find_if(specs_.begin(), specs_.end(), [&](const SettingSpec& s) { return s.key == key; });
    return it == specs_.end() ? nullptr : &*it;
}

void Settings::assign(const std::string& assignment, const std::string& origin) {
    const auto eq = assignment.find('=');
    if (eq == std::string::npos || eq == 0)
        throwInputError(origin, assignment, "", "expected KEY=VALUE");
    set(assignment.substr(0, eq), assignment.substr(eq + 1), origin);
}

void Settings::set(const std::string& key, const std::string& value, const std::string& origin) {
    if (!declared(key)) {
        std::string known;
        for (const auto& d : specs_) known += (known.empty() ? "" : ", ") + d.key;
        throwInputError(origin, key, "", "unknown setting (known: " + (known.empty() ? std::string("none") : known) + ")");
    }
    values_[key] = value;
    origins_[key] = origin;
    defaults_.erase(key);
}

void Settings::setDefault(const std::string& key, const std::string& value, const std::string& origin) {
    if (declared(key) && has(key)) return;  // the command line (or an earlier source) wins
    set(key, value, origin);              // throws for an undeclared key
    defaults_.insert(key);
}

std::string Settings::origin(const std::string& key) const {
    const auto it = origins_.find(key);
    return it == origins_.end() ? std::string() : it->second;
}

std::optional<std::string> Settings::text(const std::string& key) const {
    const auto it = values_.find(key);
    if (it == values_.end()) return std::nullopt;
    return it->second;
}

std::optional<SettingValue> Settings::read(const std::string& key) const {
    const auto it = values_.find(key);
    if (it == values_.end()) return std::nullopt;
    const SettingSpec* spec = find(key);
    if (spec == nullptr) throw std::logic_error("setting '" + key + "' read but never declared");
    return parseValue(*spec, it->second, origins_.at(key));
}

void Settings::validate() const {
    for (const auto& [key, value] : values_) (void)read(key);
}

SettingSpec qualityTierSpec() {
    return {.key = "quality",
            .help = "the quality tier: exact evaluates every correction, balanced and fast light each particle once per frame "
                    "(docs/PERFORMANCE.md); a setting given explicitly wins over its tier",
            .type = SettingType::Choice,
            .words = {kQualityTierNames.begin(), kQualityTierNames.end()},
            .defaultValue = "exact (sandbox render: balanced, sandbox edit: fast)"};
}

QualityTier readQualityTier(const Settings& settings) {
    if (!settings.declared("quality")) return QualityTier::Exact;
    const auto value = settings.read("quality");
    return value ? static_cast<QualityTier>(value->wordIndex) : QualityTier::Exact;
}

}  // namespace nimbus
