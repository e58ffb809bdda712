#include "gltf_accessor.h"

#include <algorithm>
#include <cstring>

#include "nimbus/base/error.h"

namespace nimbus::assets {
namespace {

// One component as double: normalized integers per glTF 2.0 §3.11 ("Animations") / accessor rules.
double readComponent(const unsigned char* p, int componentType, bool normalized) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE: {
            std::int8_t v;
            std::memcpy(&v, p, 1);
            return normalized ? std::max(v / 127.0, -1.0) : v;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: {
            std::uint8_t v;
            std::memcpy(&v, p, 1);
            return normalized ? v / 255.0 : v;
        }
        case TINYGLTF_COMPONENT_TYPE_SHORT: {
            std::int16_t v;
            std::memcpy(&v, p, 2);
            return normalized ? std::max(v / 32767.0, -1.0) : v;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            std::uint16_t v;
            std::memcpy(&v, p, 2);
            return normalized ? v / 65535.0 : v;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
            std::uint32_t v;
            std::memcpy(&v, p, 4);
            return v;
        }
        case TINYGLTF_COMPONENT_TYPE_INT: {
            std::int32_t v;
            std::memcpy(&v, p, 4);
            return v;
        }
        case TINYGLTF_COMPONENT_TYPE_FLOAT: {
            float v;
            std::memcpy(&v, p, 4);
            return v;
        }
        default: return 0.0;
    }
}

// The bytes of buffer view `view` after checking they lie inside the loaded buffer.
const unsigned char* viewBytes(const tinygltf::Model& model, int view, std::size_t& length, const std::string& file,
                               const std::string& object, const std::string& field) {
    if (view < 0 || static_cast<std::size_t>(view) >= model.bufferViews.size())
        throwInputError(file, object, field, "buffer view index " + std::to_string(view) + " is out of range");
    const tinygltf::BufferView& bv = model.bufferViews[static_cast<std::size_t>(view)];
    if (bv.buffer < 0 || static_cast<std::size_t>(bv.buffer) >= model.buffers.size())
        throwInputError(file, "bufferViews[" + std::to_string(view) + "]", "buffer", "index out of range");
    const std::vector<unsigned char>& data = model.buffers[static_cast<std::size_t>(bv.buffer)].data;
    if (bv.byteOffset > data.size() || bv.byteLength > data.size() - bv.byteOffset)
        throwInputError(file, "bufferViews[" + std::to_string(view) + "]", "byteLength",
                        "the view runs past the end of its buffer (" + std::to_string(data.size()) + " bytes)");
    length = bv.byteLength;
    return data.data() + bv.byteOffset;
}

// Calls sink(elementIndex, componentIndex, value) for every component of the accessor, dense part
// first, then the sparse substitutions.
template <class Sink>
void forEachComponent(const tinygltf::Model& model, int index, const std::string& file, Sink&& sink) {
    if (index < 0 || static_cast<std::size_t>(index) >= model.accessors.size())
        throwInputError(file, "accessors[" + std::to_string(index) + "]", "", "accessor index out of range");
    const tinygltf::Accessor& a = model.accessors[static_cast<std::size_t>(index)];
    const std::string object = describeAccessor(model, index);
    const ElementLayout layout = elementLayout(a.componentType, a.type);
    if (layout.elementSize == 0) throwInputError(file, object, "componentType", "unknown component type or type");

    if (a.bufferView >= 0) {
        std::size_t length = 0;
        const unsigned char* base = viewBytes(model, a.bufferView, length, file, object, "bufferView");
        const int declaredStride = model.bufferViews[static_cast<std::size_t>(a.bufferView)].byteStride;
        const std::size_t stride = declaredStride > 0 ? static_cast<std::size_t>(declaredStride) : layout.elementSize;
        if (stride < layout.elementSize)
            throwInputError(file, object, "bufferView", "byteStride " + std::to_string(stride) +
                                                            " is smaller than the element size " +
                                                            std::to_string(layout.elementSize));
        const std::uint64_t end = static_cast<std::uint64_t>(a.byteOffset) +
                                  static_cast<std::uint64_t>(stride) * (a.count - 1) + layout.elementSize;
        if (a.count == 0 || end > length)
            throwInputError(file, object, "count", "elements end at byte " + std::to_string(end) +
                                                       " of a buffer view of " + std::to_string(length) + " bytes");
        const int rows = layout.components / layout.columns;
        for (std::size_t e = 0; e < a.count; ++e) {
            const unsigned char* element = base + a.byteOffset + e * stride;
            for (int col = 0; col < layout.columns; ++col)
                for (int r = 0; r < rows; ++r)
                    sink(e, col * rows + r,
                         readComponent(element + col * layout.columnStride + static_cast<std::size_t>(r) * layout.componentSize,
                                       a.componentType, a.normalized));
        }
    }
    // Without a buffer view the dense part is all zeros, which the caller's initial fill provides.

    if (!a.sparse.isSparse) return;
    const std::size_t count = static_cast<std::size_t>(a.sparse.count);
    const int indexType = a.sparse.indices.componentType;
    const ElementLayout indexLayout = elementLayout(indexType, TINYGLTF_TYPE_SCALAR);
    if (indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
        throwInputError(file, object, "sparse.indices.componentType", "must be an unsigned integer type");
    if (a.sparse.count <= 0 || count > a.count)
        throwInputError(file, object, "sparse.count", "must be in [1, count]");
    std::size_t indicesLength = 0, valuesLength = 0;
    const unsigned char* indices = viewBytes(model, a.sparse.indices.bufferView, indicesLength, file, object, "sparse.indices.bufferView");
    const unsigned char* values = viewBytes(model, a.sparse.values.bufferView, valuesLength, file, object, "sparse.values.bufferView");
    const std::uint64_t indicesOffset = static_cast<std::uint64_t>(std::max(a.sparse.indices.byteOffset, 0));
    const std::uint64_t valuesOffset = static_cast<std::uint64_t>(std::max(a.sparse.values.byteOffset, 0));
    if (indicesOffset + count * indexLayout.elementSize > indicesLength)
        throwInputError(file, object, "sparse.indices", "runs past the end of its buffer view");
    if (valuesOffset + count * layout.elementSize > valuesLength)
        throwInputError(file, object, "sparse.values", "runs past the end of its buffer view");
    const int rows = layout.components / layout.columns;
    std::uint64_t previous = 0;
    for (std::size_t s = 0; s < count; ++s) {
        const auto target = static_cast<std::uint64_t>(
            readComponent(indices + indicesOffset + s * indexLayout.elementSize, indexType, false));
        if (target >= a.count)
            throwInputError(file, object, "sparse.indices", "index " + std::to_string(target) + " (entry " +
                                                                std::to_string(s) + ") is not below count " +
                                                                std::to_string(a.count));
        if (s > 0 && target <= previous)
            throwInputError(file, object, "sparse.indices", "indices must strictly increase (entry " + std::to_string(s) + ")");
        previous = target;
        const unsigned char* element = values + valuesOffset + s * layout.elementSize;
        for (int col = 0; col < layout.columns; ++col)
            for (int r = 0; r < rows; ++r)
                sink(static_cast<std::size_t>(target), col * rows + r,
                     readComponent(element + col * layout.columnStride + static_cast<std::size_t>(r) * layout.componentSize,
                                   a.componentType, a.normalized));
    }
}

}  // namespace

int accessorTypeFromString(const std::string& type) {
    if (type == "SCALAR") return TINYGLTF_TYPE_SCALAR;
    if (type == "VEC2") return TINYGLTF_TYPE_VEC2;
    if (type == "VEC3") return TINYGLTF_TYPE_VEC3;
    if (type == "VEC4") return TINYGLTF_TYPE_VEC4;
    if (type == "MAT2") return TINYGLTF_TYPE_MAT2;
    if (type == "MAT3") return TINYGLTF_TYPE_MAT3;
    if (type == "MAT4") return TINYGLTF_TYPE_MAT4;
    return 0;
}

const char* accessorTypeName(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR: return "SCALAR";
        case TINYGLTF_TYPE_VEC2: return "VEC2";
        case TINYGLTF_TYPE_VEC3: return "VEC3";
        case TINYGLTF_TYPE_VEC4: return "VEC4";
        case TINYGLTF_TYPE_MAT2: return "MAT2";
        case TINYGLTF_TYPE_MAT3: return "MAT3";
        case TINYGLTF_TYPE_MAT4: return "MAT4";
        default: return "unknown type";
    }
}

const char* componentTypeName(int componentType) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE: return "BYTE";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return "UNSIGNED_BYTE";
        case TINYGLTF_COMPONENT_TYPE_SHORT: return "SHORT";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return "UNSIGNED_SHORT";
        case TINYGLTF_COMPONENT_TYPE_INT: return "INT";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return "UNSIGNED_INT";
        case TINYGLTF_COMPONENT_TYPE_FLOAT: return "FLOAT";
        default: return "unknown component type";
    }
}

int componentsInType(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR: return 1;
        case TINYGLTF_TYPE_VEC2: return 2;
        case TINYGLTF_TYPE_VEC3: return 3;
        case TINYGLTF_TYPE_VEC4: return 4;
        case TINYGLTF_TYPE_MAT2: return 4;
        case TINYGLTF_TYPE_MAT3: return 9;
        case TINYGLTF_TYPE_MAT4: return 16;
        default: return 0;
    }
}

ElementLayout elementLayout(int componentType, int type) {
    ElementLayout l;
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: l.componentSize = 1; break;
        case TINYGLTF_COMPONENT_TYPE_SHORT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: l.componentSize = 2; break;
        case TINYGLTF_COMPONENT_TYPE_INT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        case TINYGLTF_COMPONENT_TYPE_FLOAT: l.componentSize = 4; break;
        default: return {};
    }
    l.components = componentsInType(type);
    if (l.components == 0) return {};
    const bool matrix = type == TINYGLTF_TYPE_MAT2 || type == TINYGLTF_TYPE_MAT3 || type == TINYGLTF_TYPE_MAT4;
    l.columns = matrix ? type - 32 : 1;
    const std::size_t rows = static_cast<std::size_t>(l.components / l.columns);
    // glTF: each matrix column starts on a 4-byte boundary (MAT2/MAT3 of bytes or shorts are padded).
    l.columnStride = matrix ? (rows * l.componentSize + 3) / 4 * 4 : rows * l.componentSize;
    l.elementSize = l.columnStride * static_cast<std::size_t>(l.columns);
    return l;
}

std::string describeAccessor(const tinygltf::Model& model, int accessor) {
    const std::string where = "accessors[" + std::to_string(accessor) + "]";
    if (accessor >= 0 && static_cast<std::size_t>(accessor) < model.accessors.size()) {
        const std::string& name = model.accessors[static_cast<std::size_t>(accessor)].name;
        if (!name.empty()) return "accessor \"" + name + "\" (" + where + ")";
    }
    return where;
}

std::vector<float> readAccessorFloats(const tinygltf::Model& model, int accessor, const std::string& file) {
    if (accessor < 0 || static_cast<std::size_t>(accessor) >= model.accessors.size())
        throwInputError(file, "accessors[" + std::to_string(accessor) + "]", "", "accessor index out of range");
    const tinygltf::Accessor& a = model.accessors[static_cast<std::size_t>(accessor)];
    const std::size_t components = static_cast<std::size_t>(std::max(componentsInType(a.type), 0));
    std::vector<float> out(a.count * components, 0.0f);
    forEachComponent(model, accessor, file, [&](std::size_t e, int c, double v) {
        out[e * components + static_cast<std::size_t>(c)] = static_cast<float>(v);
    });
    return out;
}

std::vector<std::uint32_t> readAccessorIndices(const tinygltf::Model& model, int accessor, const std::string& file) {
    if (accessor < 0 || static_cast<std::size_t>(accessor) >= model.accessors.size())
        throwInputError(file, "accessors[" + std::to_string(accessor) + "]", "", "accessor index out of range");
    const tinygltf::Accessor& a = model.accessors[static_cast<std::size_t>(accessor)];
    if (a.type != TINYGLTF_TYPE_SCALAR ||
        (a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
         a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
         a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT) ||
        a.normalized)
        throwInputError(file, describeAccessor(model, accessor), "componentType",
                        "indices must be SCALAR UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT, not normalized");
    std::vector<std::uint32_t> out(a.count, 0);
    forEachComponent(model, accessor, file, [&](std::size_t e, int, double v) { out[e] = static_cast<std::uint32_t>(v); });
    return out;
}

}  // namespace nimbus::assets
