#pragma once
// The viewport: the live real-time render of the editor's state, shown in an ImGui window, with
// an orbit/pan/zoom camera or the view through a scene camera, click-to-select, the transform
// gizmo, media bounds and light icons, and the reference snapshot's error heat map.
//
// Does not: render when nothing it shows changed, unless asked (playing, `frames N`, benchmarks).
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "editor_state.h"
#include "nimbus/gpu/gl_objects.h"
#include "nimbus/gpu/pass_timer.h"
#include "services/reference_snapshot.h"
#include "services/scene_overlays.h"
#include "services/viewport_display.h"
#include "viewport/gizmo.h"
#include "viewport/orbit_camera.h"

namespace nimbus::sandbox::editor {

class ViewportPanel {
public:
    // `fixedSize`: render at this size whatever the window's size (scripts, benchmarks).
    explicit ViewportPanel(std::optional<glm::ivec2> fixedSize = std::nullopt);

    // Renders a new frame when the state changed since the last one, or always with `force`.
    // Needs the window's GL context current; call before the ImGui frame draws.
    void render(EditorState& state, bool force);
    // The ImGui window: image, overlays, camera input, picking, gizmo. Edits go through `state`;
    // a refused one is returned as its message.
    std::optional<std::string> draw(EditorState& state, ReferenceSnapshot& snapshot);

    // The last frame, linear, read back from the renderer on first use.
    const assets::RgbImage& image(EditorState& state);
    glm::ivec2 size() const { return renderedSize_; }
    std::uint64_t renderedRevision() const { return renderedRevision_; }
    double lastFrameMs() const { return lastFrameMs_; }
    const gpu::GlPassTimer& timer() const { return timer_; }
    int renderedFrames() const { return frames_; }

    // What the viewport looks through: a scene camera ("" : the scene's first) or the free camera.
    void viewThrough(const std::string& camera);
    void useFreeCamera(EditorState& state);
    bool freeCamera() const { return free_; }
    const std::string& sceneCamera() const { return sceneCamera_; }
    // The free camera as the renderer takes it; nullptr when looking through a scene camera.
    const assets::ResolvedCamera* cameraOverride() const { return free_ ? &freeResolved_ : nullptr; }
    void frameSelection(EditorState& state);
    // Where new nodes go: `distance` metres ahead of the camera the viewport shows.
    glm::dvec3 pointAhead(EditorState& state, double distance) const;

    GizmoMode gizmoMode = GizmoMode::Translate;
    bool showHeatMap = true;
    bool showBounds = true;

private:
    assets::ResolvedCamera shownCamera(EditorState& state) const;
    void uploadHeat(const assets::RgbImage& heat);
    void handleCamera(EditorState& state, bool hovered);
    std::optional<std::string> handleGizmo(EditorState& state, glm::dvec2 origin, bool& gizmoHovered);
    void drawOverlays(EditorState& state, glm::dvec2 origin);
    void pickAt(EditorState& state, glm::dvec2 pixel);
    const std::vector<NodeOverlay>& overlays(EditorState& state);

    std::optional<glm::ivec2> fixedSize_;
    glm::ivec2 size_{640, 360};
    assets::RgbImage image_;
    bool imageStale_ = true;
    std::unique_ptr<ViewportDisplay> display_;  // made with the first frame, when a context is current
    gpu::Texture heatTexture_;
    std::uint64_t heatRevision_ = ~0ull;
    std::uint64_t renderedRevision_ = ~0ull;
    glm::ivec2 renderedSize_{0, 0};
    double lastFrameMs_ = 0.0;
    int frames_ = 0;
    gpu::GlPassTimer timer_;

    bool free_ = false;
    std::string sceneCamera_;
    OrbitCamera orbit_;
    assets::ResolvedCamera freeResolved_;
    GizmoState gizmo_;
    std::vector<NodeOverlay> overlays_;
    std::uint64_t overlaysRevision_ = ~0ull;
    bool freeChanged_ = false;
};

}  // namespace nimbus::sandbox::editor
