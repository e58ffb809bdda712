#pragma once
// Turning glTF mesh primitives into Nimbus triangle lists: strips and fans expanded, points and
// lines dropped (with a warning), non-indexed primitives indexed 0..n-1, flat normals computed
// (vertices unwelded) when the file has none, as the glTF spec asks. Checks the data itself:
// finite positions / normals / texture coordinates and index values below the vertex count.
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include "nimbus/assets/scene.h"

namespace nimbus::assets {

std::vector<Mesh> buildMeshes(const tinygltf::Model& model, const nlohmann::json& root, const std::string& file);

// Unit normal of triangle (a, b, c), counter-clockwise front. Degenerate triangles (collinear or
// coincident points) get a unit vector perpendicular to their longest edge, or +Y: never NaN.
glm::vec3 triangleNormal(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c);

}  // namespace nimbus::assets
