#include "media/tiny_document.h"

#include <tiny_gltf.h>

#include "animation.h"
#include "gltf_data.h"

namespace mini {

std::string TinyDocument::displayName() const { return scene_->path.filename().string(); }

const nlohmann::json* TinyDocument::mediaExtension(std::size_t node) const {
    const nlohmann::json& media = scene_->nodes.at(node).media;
    return media.is_null() ? nullptr : &media;
}

std::size_t TinyDocument::accessorCount(int accessor, const std::string& node, const std::string& field) const {
    const std::string where = node + ": " + field;
    if (accessor < 0 || static_cast<std::size_t>(accessor) >= scene_->model->accessors.size())
        throw SceneError(displayName() + ": " + where + ": accessor does not exist");
    const int components = tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(scene_->model->accessors[static_cast<std::size_t>(accessor)].type));
    return gltf::accessorCount(*scene_->model, accessor, components > 0 ? components : 1, displayName() + ": " + where);
}

std::vector<float> TinyDocument::readFloats(int accessor, int components, const std::string& node, const std::string& field) const {
    return gltf::readFloats(*scene_->model, accessor, components, displayName() + ": " + node + ": " + field);
}

std::vector<glm::dmat4> TinyDocument::worldTransforms(double timeSeconds) const { return worldTransformsAt(*scene_, timeSeconds); }

}  // namespace mini
