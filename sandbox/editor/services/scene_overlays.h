#pragma once
// What the viewport draws over the render and picks against, per node of the current state:
// world bounds of meshes and media, and icons for lights and cameras.
//
// Does not: draw (ViewportPanel does) or look at nodes that show nothing.
#include <vector>

#include <glm/glm.hpp>

#include "nimbus/base/aabb.h"
#include "session.h"

namespace nimbus::sandbox::editor {

enum class OverlayKind { Mesh, Media, Light, Camera };

struct NodeOverlay {
    int node = -1;
    OverlayKind kind = OverlayKind::Mesh;
    Aabb box;                              // world bounds (meshes and media)
    glm::dvec3 position{0.0};              // world origin of the node
    glm::dvec3 direction{0.0, 0.0, -1.0};  // the node's −Z (lights and cameras look along it)
    bool directional = false;              // a directional light
};

std::vector<NodeOverlay> collectOverlays(Session& session);

// The node's world matrix and its parent's (identity for a root), at the session's time.
glm::dmat4 nodeWorld(Session& session, int node);
glm::dmat4 parentWorld(Session& session, int node);

}  // namespace nimbus::sandbox::editor
