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
        std::string help;  // what it does and its default, for `sandbox render --help-settings`
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

    bool has(const std::string& key) const { return values_.count(key) != 0; }
    void unset(const std::string& key) {
        values_.erase(key);
        origins_.erase(key);
    }
    std::string origin(const std::string& key) const;
    // Typed reads: std::nullopt when unset; InputError naming the key when the value does not parse
    // or lies outside [min, max].
    std::optional<double> number(const std::string& key, double min, double max) const;
    std::optional<long long> integer(const std::string& key, long long min, long long max) const;
    std::optional<bool> boolean(const std::string& key) const;
    std::optional<std::string> text(const std::string& key) const;

private:
    std::vector<Declaration> declarations_;
    std::map<std::string, std::string> values_;
    std::map<std::string, std::string> origins_;
};

}  // namespace nimbus
