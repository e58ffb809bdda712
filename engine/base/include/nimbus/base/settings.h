#pragma once
// Named settings a user can fix from the command line (`--set KEY=VALUE`) or a scene, declared by
// the modules that read them (setting_spec.h). An undeclared key or a value the spec does not
// accept is an InputError naming where the value came from, so a typo never silently does nothing.
//
// Does not: hold what a quality tier picks. A module reads its typed struct for the tier and
// applies the keys set here on top (readFields).
#include <map>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <vector>

#include "nimbus/base/setting_spec.h"

namespace nimbus {

class Settings {
public:
    // Declaring a key again with the same spec is harmless; with another type, range or words it
    // is a programming error (std::logic_error), since each key is declared once.
    void declare(const SettingSpec& spec);
    bool declared(const std::string& key) const { return find(key) != nullptr; }
    // In declaration order.
    const std::vector<SettingSpec>& declarations() const { return specs_; }
    const SettingSpec* find(const std::string& key) const;

    // "KEY=VALUE"; throws InputError for a malformed assignment or an undeclared key.
    void assign(const std::string& assignment, const std::string& origin = "--set");
    void set(const std::string& key, const std::string& value, const std::string& origin = "--set");

    // A value from a lower-priority source (a scene's defaults): kept only when the key is unset,
    // so the command line wins. Throws InputError for an undeclared key.
    void setDefault(const std::string& key, const std::string& value, const std::string& origin);

    bool has(const std::string& key) const { return values_.count(key) != 0; }
    // Whether the value came from setDefault (a scene's defaults), not from the user's own choice.
    bool isDefault(const std::string& key) const { return defaults_.count(key) != 0; }
    void unset(const std::string& key) {
        values_.erase(key);
        origins_.erase(key);
        defaults_.erase(key);
    }
    // Where the value comes from: "--set", "--quality", a scene's node and field. Empty when unset.
    std::string origin(const std::string& key) const;
    // The value as it was given; std::nullopt when unset.
    std::optional<std::string> text(const std::string& key) const;

    // The value checked against the key's spec; std::nullopt when unset. InputError naming the
    // origin and the key when it does not parse, lies outside the range or is not one of the words.
    std::optional<SettingValue> read(const std::string& key) const;
    // Every key that was set, checked against its spec (what a scene or a command line got wrong
    // is refused at once, not when some mode reads it).
    void validate() const;

private:
    std::vector<SettingSpec> specs_;
    std::map<std::string, std::string> values_;
    std::map<std::string, std::string> origins_;
    std::set<std::string> defaults_;
};

// `start` (a tier's typed settings) with every key of `fields` that was set applied, in order.
template <class S>
S readFields(const Settings& settings, std::type_identity_t<std::span<const SettingField<S>>> fields, S start) {
    for (const SettingField<S>& f : fields)
        if (const auto value = settings.read(f.spec.key)) f.apply(start, *value);
    return start;
}

// The declared settings' values as a user would type them, for messages: "%g" without trailing noise.
std::string formatSettingNumber(double value);

}  // namespace nimbus
