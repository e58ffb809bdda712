// Accessor reads for plugins after loading (particle positions, radii, ...): the references come
// from extension JSON the loader does not interpret, so they are checked here, on every read.
#include <cmath>

#include "document.h"
#include "gltf_accessor.h"
#include "nimbus/assets/scene.h"
#include "nimbus/base/error.h"

namespace nimbus::assets {
namespace {

const tinygltf::Accessor& checkedAccessor(const Scene& scene, int accessor, const std::string& object, const std::string& field) {
    if (!scene.document) throwInputError(scene.displayName(), object, field, "the scene has no glTF document to read accessors from");
    const tinygltf::Model& model = scene.document->model;
    if (accessor < 0 || static_cast<std::size_t>(accessor) >= model.accessors.size())
        throwInputError(scene.displayName(), object, field, "accessor index " + std::to_string(accessor) +
                                                                " is out of range: the file has " +
                                                                std::to_string(model.accessors.size()) + " accessors");
    return model.accessors[static_cast<std::size_t>(accessor)];
}

const char* typeForComponents(int components) {
    switch (components) {
        case 1: return "SCALAR";
        case 2: return "VEC2";
        case 3: return "VEC3";
        case 4: return "VEC4";
        case 9: return "MAT3";
        case 16: return "MAT4";
        default: return "an unsupported type";
    }
}

}  // namespace

std::vector<float> readFloatAccessor(const Scene& scene, int accessor, int components, const std::string& object,
                                     const std::string& field) {
    const tinygltf::Accessor& a = checkedAccessor(scene, accessor, object, field);
    const tinygltf::Model& model = scene.document->model;
    const std::string name = describeAccessor(model, accessor);
    const std::string expected = std::string(typeForComponents(components)) + " FLOAT";
    const bool typeMatches = accessorTypeFromString(typeForComponents(components)) == a.type;
    if (a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT || !typeMatches)
        throwInputError(scene.displayName(), object, field, name + " is " + accessorTypeName(a.type) + " " +
                                                                componentTypeName(a.componentType) + ", expected " + expected);
    if (a.normalized) throwInputError(scene.displayName(), object, field, name + " is normalized, expected plain FLOAT");
    if (a.sparse.isSparse) throwInputError(scene.displayName(), object, field, name + " is sparse, which is not supported here");
    std::vector<float> values = readAccessorFloats(model, accessor, scene.displayName());
    for (std::size_t i = 0; i < values.size(); ++i)
        if (!std::isfinite(values[i]))
            throwInputError(scene.displayName(), object, field, name + " element " + std::to_string(i / static_cast<std::size_t>(components)) +
                                                                    " is not finite");
    return values;
}

std::size_t accessorCount(const Scene& scene, int accessor, const std::string& object, const std::string& field) {
    return checkedAccessor(scene, accessor, object, field).count;
}

}  // namespace nimbus::assets
