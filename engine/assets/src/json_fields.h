#pragma once
// Typed, checked reads of glTF JSON properties. Every failure throws one InputError line
// "file: object: field: problem", so the structural checks read like a list of rules.
//
// Why not let tinygltf read them: it silently ignores a property of the wrong type (a string
// "translation" becomes the identity), and we refuse instead of guessing.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace nimbus::assets {

using Json = nlohmann::json;

// Where a value lives, for messages: the file, the object ("accessors[3]", `node "Jet" (nodes[2])`)
// and a field prefix for nested properties ("pbrMetallicRoughness.").
struct JsonPlace {
    const std::string* file = nullptr;
    std::string object;
    std::string prefix;

    // The same object, one level deeper: place.nested("spot") names fields "spot.xxx".
    JsonPlace nested(const std::string& key) const { return {file, object, prefix + key + "."}; }
    std::string field(const std::string& key) const { return prefix + key; }
    [[noreturn]] void fail(const std::string& key, const std::string& problem) const;
};

// `singular "name" (array[i])` when the object has a name, else `array[i]`.
std::string describeObject(const char* singular, const char* array, std::size_t index, const Json& object);

// A short printable form of a JSON value for messages (long strings and arrays are cut).
std::string shortJson(const Json& value);

const Json* findMember(const Json& object, const char* key);

// Objects and arrays: present and of the right JSON type, or absent (nullptr).
const Json* optionalObject(const JsonPlace& place, const Json& object, const char* key);
const Json* optionalArray(const JsonPlace& place, const Json& object, const char* key);
const Json& requiredObject(const JsonPlace& place, const Json& object, const char* key);

// Integers: JSON integers only (1.0 is refused, as the glTF schema says), within [min, max].
std::optional<std::int64_t> optionalInteger(const JsonPlace& place, const Json& object, const char* key,
                                            std::int64_t min, std::int64_t max);
std::int64_t requiredInteger(const JsonPlace& place, const Json& object, const char* key, std::int64_t min,
                             std::int64_t max);

// An index into a top-level array of `count` elements named `arrayName`.
std::optional<int> optionalIndex(const JsonPlace& place, const Json& object, const char* key, std::size_t count,
                                 const char* arrayName);
int requiredIndex(const JsonPlace& place, const Json& object, const char* key, std::size_t count,
                  const char* arrayName);
void checkIndexValue(const JsonPlace& place, const std::string& field, const Json& value, std::size_t count,
                     const char* arrayName);

// Finite numbers within [min, max].
std::optional<double> optionalNumber(const JsonPlace& place, const Json& object, const char* key, double min,
                                     double max);
double requiredNumber(const JsonPlace& place, const Json& object, const char* key, double min, double max);

// An array of exactly `size` finite numbers within [min, max] (empty when absent).
std::vector<double> optionalNumberArray(const JsonPlace& place, const Json& object, const char* key,
                                        std::size_t size, double min, double max);

std::optional<bool> optionalBool(const JsonPlace& place, const Json& object, const char* key);
std::optional<std::string> optionalString(const JsonPlace& place, const Json& object, const char* key);
std::string requiredString(const JsonPlace& place, const Json& object, const char* key);

// A string that must be one of `allowed`.
std::optional<std::string> optionalEnum(const JsonPlace& place, const Json& object, const char* key,
                                        const std::vector<std::string>& allowed);
// An integer enum (GL constants) that must be one of `allowed`.
std::optional<std::int64_t> optionalIntegerEnum(const JsonPlace& place, const Json& object, const char* key,
                                                const std::vector<std::int64_t>& allowed);

}  // namespace nimbus::assets
