#pragma once
// Small helpers shared by the structural checks (gltf_check_data.cpp, gltf_check_scene.cpp).
#include <limits>

#include "gltf_checks.h"
#include "json_fields.h"

namespace nimbus::assets {

// Upper bound for values the spec leaves open (finite is checked separately).
inline constexpr double kHuge = std::numeric_limits<double>::max();

// Calls fn(index, object, place) for every element of the top-level array `key`, refusing a
// non-array or a non-object element.
template <class Fn>
void forEachObject(const GltfCheckInput& in, const char* key, const char* singular, Fn&& fn) {
    const JsonPlace top{&in.file, "glTF root", ""};
    const Json* array = optionalArray(top, *in.root, key);
    if (!array) return;
    for (std::size_t i = 0; i < array->size(); ++i) {
        const Json& element = (*array)[i];
        const JsonPlace place{&in.file, describeObject(singular, key, i, element), ""};
        if (!element.is_object()) place.fail("", "must be a JSON object");
        optionalString(place, element, "name");
        fn(i, element, place);
    }
}

}  // namespace nimbus::assets
