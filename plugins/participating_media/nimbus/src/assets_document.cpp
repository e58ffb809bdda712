#include "nimbus/media/nimbus/assets_document.h"

#include "nimbus/assets/scene_queries.h"

namespace nimbus::media {

const nlohmann::json* AssetsDocument::mediaExtension(std::size_t node) const {
    const nlohmann::json& extensions = scene_.nodes.at(node).extensions;
    if (!extensions.is_object() || !extensions.contains(kMediaExtension)) return nullptr;
    return &extensions[kMediaExtension];
}

std::size_t AssetsDocument::accessorCount(int accessor, const std::string& node, const std::string& field) const {
    return assets::accessorCount(scene_, accessor, node, field);
}

std::vector<float> AssetsDocument::readFloats(int accessor, int components, const std::string& node, const std::string& field) const {
    return assets::readFloatAccessor(scene_, accessor, components, node, field);
}

std::vector<glm::dmat4> AssetsDocument::worldTransforms(double timeSeconds) const {
    return assets::computeWorldTransforms(scene_, timeSeconds);
}

}  // namespace nimbus::media
