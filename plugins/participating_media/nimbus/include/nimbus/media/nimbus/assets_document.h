#pragma once
// Nimbus's loaded scene (assets::Scene) as the document the plugin's glTF part reads.
#include "nimbus/assets/scene.h"
#include "nimbus/media/gltf_document.h"

namespace nimbus::media {

class AssetsDocument final : public GltfDocument {
public:
    explicit AssetsDocument(const assets::Scene& scene) : scene_(scene) {}  // keeps a reference
    std::string displayName() const override { return scene_.displayName(); }
    std::size_t nodeCount() const override { return scene_.nodes.size(); }
    std::string nodeName(std::size_t node) const override { return scene_.nodes.at(node).name; }
    const nlohmann::json* mediaExtension(std::size_t node) const override;
    std::size_t accessorCount(int accessor, const std::string& node, const std::string& field) const override;
    std::vector<float> readFloats(int accessor, int components, const std::string& node, const std::string& field) const override;
    std::vector<glm::dmat4> worldTransforms(double timeSeconds) const override;

private:
    const assets::Scene& scene_;
};

}  // namespace nimbus::media
