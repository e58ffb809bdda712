#pragma once
// mini_host's loaded scene as the document the media plugin's glTF part reads (its "backend" for
// nimbus/media/gltf_document.h): node names and extension objects from gltf_scene, accessors
// through tinygltf, world transforms from mini_host's own animation code.
#include "gltf_scene.h"
#include "nimbus/media/gltf_document.h"

namespace mini {

class TinyDocument final : public nimbus::media::GltfDocument {
public:
    explicit TinyDocument(std::shared_ptr<const Scene> scene) : scene_(std::move(scene)) {}
    std::string displayName() const override;
    std::size_t nodeCount() const override { return scene_->nodes.size(); }
    std::string nodeName(std::size_t node) const override { return scene_->nodes.at(node).name; }
    const nlohmann::json* mediaExtension(std::size_t node) const override;
    std::size_t accessorCount(int accessor, const std::string& node, const std::string& field) const override;
    std::vector<float> readFloats(int accessor, int components, const std::string& node, const std::string& field) const override;
    std::vector<glm::dmat4> worldTransforms(double timeSeconds) const override;

private:
    std::shared_ptr<const Scene> scene_;
};

}  // namespace mini
