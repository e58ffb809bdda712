#pragma once
// Node animations (translation / rotation / scale channels) read from a checked glTF document.
// Morph-target weights channels are ignored with a warning; channels without a target node are
// skipped, as glTF says. Checks key data: finite, strictly increasing times, finite values and
// non-zero rotation quaternions.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include "nimbus/assets/scene.h"

namespace nimbus::assets {

// The channel structure comes from the JSON (tinygltf silently drops channels without a node,
// which would shift indices); the key data comes from the model's buffers.
std::vector<Animation> buildAnimations(const tinygltf::Model& model, const nlohmann::json& root, const std::string& file);

}  // namespace nimbus::assets
