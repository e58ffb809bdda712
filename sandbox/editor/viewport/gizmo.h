#pragma once
// The viewport's transform gizmo (translate along world axes, rotate about world axes, scale along the
// node's own axes) with a constant on-screen size, and the overlays drawn with it (boxes, light icons).
// The hit test and the drag are pure functions of the camera and the mouse, so they are tested without ImGui.
//
// Does not: edit the document or keep undo history (the caller commits `released` drags), or snap.
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "nimbus/assets/scene_queries.h"
#include "nimbus/base/aabb.h"

struct ImDrawList;

namespace nimbus::sandbox::editor {

enum class GizmoMode { Translate, Rotate, Scale };

struct LocalTransform {
    glm::dvec3 translation{0.0};
    glm::dquat rotation{1.0, 0.0, 0.0, 0.0};  // w, x, y, z
    glm::dvec3 scale{1.0};
};

// T·R·S split of a node matrix (shear is dropped; a mirror shows up as a negative x scale).
LocalTransform decompose(const glm::dmat4& local);
glm::dmat4 compose(const LocalTransform& t);

struct GizmoState {
    int axis = -1;  // the handle being dragged
    bool dragging = false;
    GizmoMode mode = GizmoMode::Translate;  // the mode the drag started in
    glm::dvec2 startMouse{0.0};             // viewport pixels; rotation re-bases it past a quarter turn
    LocalTransform startLocal;              // the transform `startMouse` belongs to
    LocalTransform originalLocal;           // the transform when the drag began (the undo edit's "before")
    LocalTransform current;                 // the last transform the drag produced
};

struct GizmoResult {
    bool hovered = false;   // the mouse is over a handle or dragging (the viewport must not treat a click as a pick)
    bool changed = false;   // `local` differs from the input this frame (while dragging)
    bool released = false;  // the drag ended this frame: the caller commits one undoable edit
    LocalTransform local;   // the node's new local transform
};

constexpr double kGizmoSizePixels = 90.0;

// Which handle (0=x, 1=y, 2=z, -1 none) is under `mouse` (viewport pixels) for a gizmo at the node's world
// origin, drawn `sizePixels` long on screen. An axis that points at the camera is not hittable.
int hitGizmo(GizmoMode mode, const assets::ResolvedCamera& camera, int width, int height, const glm::dmat4& nodeWorld,
             glm::dvec2 mouse, double sizePixels = kGizmoSizePixels);

// The new local transform when handle `axis` was grabbed at `startMouse` with `startLocal`, and the mouse is
// now at `mouse`. Translate: the grabbed point follows the mouse along the world axis (the move is taken into
// the parent's space through parentWorld). Rotate: about the world axis by the angle swept around the gizmo
// centre on screen (counter-clockwise on screen turns counter-clockwise as seen from the camera). Scale: the
// axis scale times the ratio of the mouse's distances along the projected axis. Returns `startLocal` when the
// drag is degenerate (axis at the camera, singular parent, camera on the centre).
LocalTransform dragGizmo(GizmoMode mode, int axis, const assets::ResolvedCamera& camera, int width, int height,
                         const glm::dmat4& parentWorld, const LocalTransform& startLocal, glm::dvec2 startMouse,
                         glm::dvec2 mouse);

// Immediate mode: draws the gizmo with `drawList` at viewport origin `origin` (screen pixels of the viewport's
// top-left) and handles ImGui's left mouse button. Needs a current ImGui context.
GizmoResult gizmo(GizmoState& state, GizmoMode mode, const assets::ResolvedCamera& camera, glm::dvec2 origin, int width,
                  int height, const glm::dmat4& parentWorld, const LocalTransform& local, ImDrawList* drawList);

// A world box's 12 edges, clipped at the near plane.
void drawBox(ImDrawList* drawList, const assets::ResolvedCamera& camera, glm::dvec2 origin, int width, int height,
             const Aabb& box, unsigned colour);

// A light as a small disc of constant screen size: with an arrow along `direction` when directional, with
// rays around it otherwise.
void drawLightIcon(ImDrawList* drawList, const assets::ResolvedCamera& camera, glm::dvec2 origin, int width, int height,
                   const glm::dvec3& position, const glm::dvec3& direction, bool directional, unsigned colour);

}  // namespace nimbus::sandbox::editor
