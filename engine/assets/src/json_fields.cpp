#include "json_fields.h"

#include <cmath>
#include <limits>

#include "nimbus/base/error.h"

namespace nimbus::assets {
namespace {

const char* typeName(const Json& v) {
    switch (v.type()) {
        case Json::value_t::null: return "null";
        case Json::value_t::object: return "an object";
        case Json::value_t::array: return "an array";
        case Json::value_t::string: return "a string";
        case Json::value_t::boolean: return "a boolean";
        case Json::value_t::number_integer:
        case Json::value_t::number_unsigned: return "an integer";
        case Json::value_t::number_float: return "a number";
        default: return "an unsupported JSON value";
    }
}

std::string joinAllowed(const std::vector<std::string>& allowed) {
    std::string out;
    for (const std::string& a : allowed) out += (out.empty() ? "\"" : ", \"") + a + "\"";
    return out;
}

std::string formatNumber(double v) {
    Json j = v;
    return j.dump();
}

// "must be >= 0" reads better than "out of range [0, 1.7976931348623157e+308]".
std::string rangeProblem(double value, double min, double max) {
    const double huge = std::numeric_limits<double>::max();
    std::string expected;
    if (max >= huge && min <= -huge) expected = "must be finite";
    else if (max >= huge) expected = "must be >= " + formatNumber(min);
    else if (min <= -huge) expected = "must be <= " + formatNumber(max);
    else expected = "must be in [" + formatNumber(min) + ", " + formatNumber(max) + "]";
    return "value " + formatNumber(value) + " is out of range: " + expected;
}

}  // namespace

void JsonPlace::fail(const std::string& key, const std::string& problem) const {
    throwInputError(file ? *file : std::string(), object, field(key), problem);
}

std::string describeObject(const char* singular, const char* array, std::size_t index, const Json& object) {
    const std::string where = std::string(array) + "[" + std::to_string(index) + "]";
    if (object.is_object()) {
        const Json* name = findMember(object, "name");
        if (name && name->is_string() && !name->get_ref<const std::string&>().empty()) {
            std::string n = name->get<std::string>();
            if (n.size() > 60) n = n.substr(0, 57) + "...";
            return std::string(singular) + " \"" + n + "\" (" + where + ")";
        }
    }
    return where;
}

std::string shortJson(const Json& value) {
    std::string text = value.dump();
    if (text.size() > 60) text = text.substr(0, 57) + "...";
    return text;
}

const Json* findMember(const Json& object, const char* key) {
    if (!object.is_object()) return nullptr;
    const auto it = object.find(key);
    return it == object.end() ? nullptr : &*it;
}

const Json* optionalObject(const JsonPlace& place, const Json& object, const char* key) {
    const Json* v = findMember(object, key);
    if (v && !v->is_object()) place.fail(key, std::string("must be a JSON object, not ") + typeName(*v));
    return v;
}

const Json* optionalArray(const JsonPlace& place, const Json& object, const char* key) {
    const Json* v = findMember(object, key);
    if (v && !v->is_array()) place.fail(key, std::string("must be a JSON array, not ") + typeName(*v));
    return v;
}

const Json& requiredObject(const JsonPlace& place, const Json& object, const char* key) {
    const Json* v = optionalObject(place, object, key);
    if (!v) place.fail(key, "is required but missing");
    return *v;
}

std::optional<std::int64_t> optionalInteger(const JsonPlace& place, const Json& object, const char* key,
                                            std::int64_t min, std::int64_t max) {
    const Json* v = findMember(object, key);
    if (!v) return std::nullopt;
    std::int64_t value = 0;
    if (v->is_number_unsigned()) {
        const std::uint64_t u = v->get<std::uint64_t>();
        if (u > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max()))
            place.fail(key, "value " + v->dump() + " is out of range [" + std::to_string(min) + ", " +
                                std::to_string(max) + "]");
        value = static_cast<std::int64_t>(u);
    } else if (v->is_number_integer()) {
        value = v->get<std::int64_t>();
    } else {
        place.fail(key, std::string("must be an integer, not ") + typeName(*v) + " (" + shortJson(*v) + ")");
    }
    if (value < min || value > max)
        place.fail(key, "value " + std::to_string(value) + " is out of range [" + std::to_string(min) + ", " +
                            std::to_string(max) + "]");
    return value;
}

std::int64_t requiredInteger(const JsonPlace& place, const Json& object, const char* key, std::int64_t min,
                             std::int64_t max) {
    const auto v = optionalInteger(place, object, key, min, max);
    if (!v) place.fail(key, "is required but missing");
    return *v;
}

void checkIndexValue(const JsonPlace& place, const std::string& field, const Json& value, std::size_t count,
                     const char* arrayName) {
    if (!value.is_number_integer())
        place.fail(field, std::string("must be an index (an integer), not ") + typeName(value) + " (" +
                              shortJson(value) + ")");
    const bool negative = value.is_number_integer() && !value.is_number_unsigned() && value.get<std::int64_t>() < 0;
    if (negative || value.get<std::uint64_t>() >= count)
        place.fail(field, "index " + value.dump() + " is out of range: the file has " + std::to_string(count) + " " +
                              arrayName);
}

std::optional<int> optionalIndex(const JsonPlace& place, const Json& object, const char* key, std::size_t count,
                                 const char* arrayName) {
    const Json* v = findMember(object, key);
    if (!v) return std::nullopt;
    checkIndexValue(place, key, *v, count, arrayName);
    return static_cast<int>(v->get<std::int64_t>());
}

int requiredIndex(const JsonPlace& place, const Json& object, const char* key, std::size_t count,
                  const char* arrayName) {
    const auto v = optionalIndex(place, object, key, count, arrayName);
    if (!v) place.fail(key, "is required but missing");
    return *v;
}

std::optional<double> optionalNumber(const JsonPlace& place, const Json& object, const char* key, double min,
                                     double max) {
    const Json* v = findMember(object, key);
    if (!v) return std::nullopt;
    if (!v->is_number()) place.fail(key, std::string("must be a number, not ") + typeName(*v) + " (" + shortJson(*v) + ")");
    const double d = v->get<double>();
    if (!std::isfinite(d)) place.fail(key, "value is not finite");
    if (d < min || d > max) place.fail(key, rangeProblem(d, min, max));
    return d;
}

double requiredNumber(const JsonPlace& place, const Json& object, const char* key, double min, double max) {
    const auto v = optionalNumber(place, object, key, min, max);
    if (!v) place.fail(key, "is required but missing");
    return *v;
}

std::vector<double> optionalNumberArray(const JsonPlace& place, const Json& object, const char* key,
                                        std::size_t size, double min, double max) {
    const Json* v = optionalArray(place, object, key);
    if (!v) return {};
    if (v->size() != size)
        place.fail(key, "must hold " + std::to_string(size) + " numbers, not " + std::to_string(v->size()));
    std::vector<double> out;
    out.reserve(size);
    for (std::size_t i = 0; i < size; ++i) {
        const Json& e = (*v)[i];
        const std::string where = std::string(key) + "[" + std::to_string(i) + "]";
        if (!e.is_number()) place.fail(where, std::string("must be a number, not ") + typeName(e));
        const double d = e.get<double>();
        if (!std::isfinite(d)) place.fail(where, "value is not finite");
        if (d < min || d > max) place.fail(where, rangeProblem(d, min, max));
        out.push_back(d);
    }
    return out;
}

std::optional<bool> optionalBool(const JsonPlace& place, const Json& object, const char* key) {
    const Json* v = findMember(object, key);
    if (!v) return std::nullopt;
    if (!v->is_boolean()) place.fail(key, std::string("must be true or false, not ") + typeName(*v));
    return v->get<bool>();
}

std::optional<std::string> optionalString(const JsonPlace& place, const Json& object, const char* key) {
    const Json* v = findMember(object, key);
    if (!v) return std::nullopt;
    if (!v->is_string()) place.fail(key, std::string("must be a string, not ") + typeName(*v));
    return v->get<std::string>();
}

std::string requiredString(const JsonPlace& place, const Json& object, const char* key) {
    const auto v = optionalString(place, object, key);
    if (!v) place.fail(key, "is required but missing");
    return *v;
}

std::optional<std::string> optionalEnum(const JsonPlace& place, const Json& object, const char* key,
                                        const std::vector<std::string>& allowed) {
    const auto v = optionalString(place, object, key);
    if (!v) return std::nullopt;
    for (const std::string& a : allowed)
        if (*v == a) return v;
    place.fail(key, "unknown value " + shortJson(Json(*v)) + " (expected one of " + joinAllowed(allowed) + ")");
}

std::optional<std::int64_t> optionalIntegerEnum(const JsonPlace& place, const Json& object, const char* key,
                                                const std::vector<std::int64_t>& allowed) {
    const auto v = optionalInteger(place, object, key, std::numeric_limits<std::int64_t>::min(),
                                   std::numeric_limits<std::int64_t>::max());
    if (!v) return std::nullopt;
    std::string list;
    for (const std::int64_t a : allowed) {
        if (*v == a) return v;
        list += (list.empty() ? "" : ", ") + std::to_string(a);
    }
    place.fail(key, "unknown value " + std::to_string(*v) + " (expected one of " + list + ")");
}

}  // namespace nimbus::assets
