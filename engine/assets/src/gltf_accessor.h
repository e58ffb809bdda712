#pragma once
// glTF accessors: the byte layout of one element, and reading an accessor's elements out of the
// loaded buffers (strided views, normalized integers, sparse substitution).
//
// Reads re-check every byte range against the buffers actually loaded, so a reader can never run
// off a buffer even when called long after loading (plugins reading particle accessors).
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <tiny_gltf.h>

namespace nimbus::assets {

// tinygltf type code (TINYGLTF_TYPE_VEC3, ...) for a JSON "type" string; 0 when unknown.
int accessorTypeFromString(const std::string& type);
const char* accessorTypeName(int type);
const char* componentTypeName(int componentType);
int componentsInType(int type);  // SCALAR 1 ... MAT4 16

struct ElementLayout {
    std::size_t componentSize = 0;
    int components = 0;        // per element, matrices included (MAT3: 9)
    int columns = 1;           // matrices: columns (each 4-byte aligned in the buffer)
    std::size_t columnStride = 0;
    std::size_t elementSize = 0;  // bytes one element occupies, column padding included
};
// Layout of one element; elementSize 0 for an unknown component type or type.
ElementLayout elementLayout(int componentType, int type);

// "accessors[3]" or `accessor "name" (accessors[3])`, for messages.
std::string describeAccessor(const tinygltf::Model& model, int accessor);

// All components of all elements as floats (count × components), matrices column-major without
// padding. Normalized integers map to [0, 1] / [-1, 1] as glTF specifies; other integers convert
// to their value. Throws InputError (naming `file` and the accessor) on a range that does not fit.
std::vector<float> readAccessorFloats(const tinygltf::Model& model, int accessor, const std::string& file);

// SCALAR unsigned byte/short/int accessor values (indices, sparse indices).
std::vector<std::uint32_t> readAccessorIndices(const tinygltf::Model& model, int accessor, const std::string& file);

}  // namespace nimbus::assets
