#pragma once
// The binary half of loading (gltf_scene.cpp does the JSON half): accessors, meshes, animations.
#include <string>
#include <vector>

#include <tiny_gltf.h>

#include "gltf_scene.h"

namespace mini::gltf {

// FLOAT accessor with `components` per element, flattened; throws SceneError naming `where`.
std::vector<float> readFloats(const tinygltf::Model& model, int accessor, int components, const std::string& where);
// Element count of an accessor (checked as readFloats checks it).
std::size_t accessorCount(const tinygltf::Model& model, int accessor, int components, const std::string& where);
// UNSIGNED_BYTE / SHORT / INT scalar accessor.
std::vector<std::uint32_t> readIndices(const tinygltf::Model& model, int accessor, const std::string& where);

std::vector<Mesh> readMeshes(const tinygltf::Model& model, const std::string& file);
std::vector<Channel> readChannels(const tinygltf::Model& model, const std::string& file);

}  // namespace mini::gltf
