#pragma once
// What the reader of the NIMBUS_participating_media extension needs of a loaded glTF document. A
// host implements it over its own loader, the way Dear ImGui's backends sit beside its core:
// Nimbus over assets::Scene (nimbus/media/nimbus/assets_document.h), the mini host over tinygltf.
//
// Does not: load files, decode images, or keep anything (the parser copies what it reads).
#include <cstddef>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

namespace nimbus::media {

inline constexpr char kMediaExtension[] = "NIMBUS_participating_media";

class GltfDocument {
public:
    virtual ~GltfDocument() = default;
    virtual std::string displayName() const = 0;  // the file, as messages name it
    virtual std::size_t nodeCount() const = 0;
    virtual std::string nodeName(std::size_t node) const = 0;
    // The node's extensions.NIMBUS_participating_media value, or null when it has none.
    virtual const nlohmann::json* mediaExtension(std::size_t node) const = 0;
    // A float accessor's element count, and its elements (`components` floats each). Both refuse a
    // missing, non-float, wrongly typed or truncated accessor with InputError naming `node` (as
    // messages write it) and `field`.
    virtual std::size_t accessorCount(int accessor, const std::string& node, const std::string& field) const = 0;
    virtual std::vector<float> readFloats(int accessor, int components, const std::string& node, const std::string& field) const = 0;
    // Every node's local-to-world matrix at `timeSeconds`, animations applied.
    virtual std::vector<glm::dmat4> worldTransforms(double timeSeconds) const = 0;
};

}  // namespace nimbus::media
