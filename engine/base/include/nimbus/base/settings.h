#pragma once
// Named settings a user can fix from the command line (`--set KEY=VALUE`) or a scene, declared by
// the modules that read them. An undeclared key or a value of the wrong form is an InputError, so
// a typo never silently does nothing.
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace nimbus {

class Settings {
public:
    struct Declaration {
        std::string key;
        std::string help;  // what it does and its default, for `sandbox settings`
    };

    // Declaring a key twice is harmless (the first help text stays).
    void declare(const std::string& key, const std::string& help);
    bool declared(const std::string& key) const;
    const std::vector<Declaration>& declarations() const { return declarations_; }

    // "KEY=VALUE"; throws InputError for a malformed assignment or an undeclared key.
    void assign(const std::string& assignment, const std::string& origin = "--set");
    void set(const std::string& key, const std::string& value, const std::string& origin = "--set");

    // A value from a lower-priority source (a scene's defaults): kept only when the key is unset,
    // so the command line wins. Throws InputError for an undeclared key.
    void setDefault(const std::string& key, const std::string& value, const std::string& origin);

    // A preset: while `key` reads `value`, each setting in `values` that nothing has set reads as
    // given there (a quality tier picking its settings). Explicit values always win. Defining the
    // same key and value again replaces the preset.
    void definePreset(const std::string& key, const std::string& value, std::map<std::string, std::string> values);
    // The values `key` can select presets with, in the order they were defined.
    std::vector<std::string> presetValues(const std::string& key) const;

    // Set from a source (the command line, a scene); a value a preset supplies does not count.
    bool has(const std::string& key) const { return values_.count(key) != 0; }
    void unset(const std::string& key) {
        values_.erase(key);
        origins_.erase(key);
    }
    // Where the value comes from: "--set", a scene's node and field, or "quality=fast" for a preset.
    std::string origin(const std::string& key) const;
    // Typed reads: std::nullopt when unset; InputError naming the key when the value does not parse
    // or lies outside [min, max].
    std::optional<double> number(const std::string& key, double min, double max) const;
    std::optional<long long> integer(const std::string& key, long long min, long long max) const;
    std::optional<bool> boolean(const std::string& key) const;
    std::optional<std::string> text(const std::string& key) const;

private:
    struct Preset {
        std::string key, value;
        std::map<std::string, std::string> values;
    };
    // The value `key` reads (set, else from a selected preset), or nullptr; `origin` is filled.
    const std::string* lookup(const std::string& key, std::string* origin) const;

    std::vector<Preset> presets_;
    std::vector<Declaration> declarations_;
    std::map<std::string, std::string> values_;
    std::map<std::string, std::string> origins_;
};

}  // namespace nimbus
