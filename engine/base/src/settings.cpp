#include "nimbus/base/settings.h"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "nimbus/base/error.h"

namespace nimbus {

void Settings::declare(const std::string& key, const std::string& help) {
    if (!declared(key)) declarations_.push_back({key, help});
}

bool Settings::declared(const std::string& key) const {
    return std::any_of(declarations_.begin(), declarations_.end(), [&](const Declaration& d) { return d.key == key; });
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
        for (const auto& d : declarations_) known += (known.empty() ? "" : ", ") + d.key;
        throwInputError(origin, key, "", "unknown setting (known: " + (known.empty() ? std::string("none") : known) + ")");
    }
    values_[key] = value;
    origins_[key] = origin;
}

void Settings::setDefault(const std::string& key, const std::string& value, const std::string& origin) {
    if (declared(key) && has(key)) return;  // the command line (or an earlier source) wins
    set(key, value, origin);              // throws for an undeclared key
}

void Settings::definePreset(const std::string& key, const std::string& value, std::map<std::string, std::string> values) {
    for (Preset& p : presets_) {
        if (p.key == key && p.value == value) {
            p.values = std::move(values);
            return;
        }
    }
    presets_.push_back({key, value, std::move(values)});
}

std::vector<std::string> Settings::presetValues(const std::string& key) const {
    std::vector<std::string> out;
    for (const Preset& p : presets_)
        if (p.key == key) out.push_back(p.value);
    return out;
}

const std::string* Settings::lookup(const std::string& key, std::string* origin) const {
    if (const auto it = values_.find(key); it != values_.end()) {
        if (origin) *origin = origins_.at(key);
        return &it->second;
    }
    for (const Preset& p : presets_) {
        const auto selected = values_.find(p.key);
        if (selected == values_.end() || selected->second != p.value) continue;
        if (const auto it = p.values.find(key); it != p.values.end()) {
            if (origin) *origin = p.key + "=" + p.value + " (from " + origins_.at(p.key) + ")";
            return &it->second;
        }
    }
    return nullptr;
}

std::string Settings::origin(const std::string& key) const {
    std::string out;
    lookup(key, &out);
    return out;
}

std::optional<double> Settings::number(const std::string& key, double min, double max) const {
    std::string where;
    const std::string* value = lookup(key, &where);
    if (value == nullptr) return std::nullopt;
    const std::string& v = *value;
    double out = 0.0;
    const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), out);
    if (ec != std::errc() || end != v.data() + v.size() || !std::isfinite(out))
        throwInputError(where, key, "", "'" + v + "' is not a number");
    if (out < min || out > max)
        throwInputError(where, key, "", v + " is outside [" + std::to_string(min) + ", " + std::to_string(max) + "]");
    return out;
}

std::optional<long long> Settings::integer(const std::string& key, long long min, long long max) const {
    std::string where;
    const std::string* value = lookup(key, &where);
    if (value == nullptr) return std::nullopt;
    const std::string& v = *value;
    long long out = 0;
    const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), out);
    if (ec != std::errc() || end != v.data() + v.size())
        throwInputError(where, key, "", "'" + v + "' is not a whole number");
    if (out < min || out > max)
        throwInputError(where, key, "", v + " is outside [" + std::to_string(min) + ", " + std::to_string(max) + "]");
    return out;
}

std::optional<bool> Settings::boolean(const std::string& key) const {
    std::string where;
    const std::string* value = lookup(key, &where);
    if (value == nullptr) return std::nullopt;
    const std::string& v = *value;
    if (v == "1" || v == "true" || v == "on" || v == "yes") return true;
    if (v == "0" || v == "false" || v == "off" || v == "no") return false;
    throwInputError(where, key, "", "'" + v + "' is not on/off");
}

std::optional<std::string> Settings::text(const std::string& key) const {
    const std::string* value = lookup(key, nullptr);
    if (value == nullptr) return std::nullopt;
    return *value;
}

}  // namespace nimbus
