#include "viewport_panel.h"

#include <epoxy/gl.h>
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cstdint>

#include "nimbus/base/error.h"
#include "nimbus/render/render_plugin.h"
#include "nimbus/scene/components.h"
#include "services/scene_overlays.h"
#include "viewport/picking.h"

namespace nimbus::sandbox::editor {
namespace {

constexpr int kTimedEvery = 10;

ImTextureID textureId(const gpu::Texture& texture) {
    return reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(texture.id()));
}

LocalTransform restPose(const assets::Node& node) {
    if (node.hasMatrix) return decompose(node.matrix);
    return {node.translation, node.rotation, node.scale};
}

// While a gizmo drag is under way the node's entity moves at once, so the render follows the mouse;
// the document only changes on release.
void previewTransform(Session& session, int node, const glm::dmat4& world) {
    session.app().world().view<scene::SceneNode, scene::Transform>().each(
        [&](ecs::Entity, const scene::SceneNode& n, scene::Transform& transform) {
            if (n.node == node) transform.world = world;
        });
}

std::vector<FieldEdit> transformEdits(int node, const LocalTransform& t, bool hadMatrix) {
    std::vector<FieldEdit> edits(hadMatrix ? 4 : 3);
    auto at = edits.begin();
    if (hadMatrix) *at++ = FieldEdit{node, "matrix", nullptr};
    *at++ = FieldEdit{node, "translation", Json::array({t.translation.x, t.translation.y, t.translation.z})};
    *at++ = FieldEdit{node, "rotation", Json::array({t.rotation.x, t.rotation.y, t.rotation.z, t.rotation.w})};
    *at = FieldEdit{node, "scale", Json::array({t.scale.x, t.scale.y, t.scale.z})};
    return edits;
}

}  // namespace

ViewportPanel::ViewportPanel(std::optional<glm::ivec2> fixedSize) : fixedSize_(fixedSize) {
    if (fixedSize_) size_ = *fixedSize_;
}

void ViewportPanel::viewThrough(const std::string& camera) {
    free_ = camera == "-";
    if (!free_) sceneCamera_ = camera;
    freeChanged_ = true;
}

void ViewportPanel::useFreeCamera(EditorState& state) {
    if (free_) return;
    const assets::ResolvedCamera shown = shownCamera(state);
    double focus = 5.0;
    if (state.selected() >= 0)
        focus = std::max(0.1, glm::dot(glm::dvec3(nodeWorld(state.session(), state.selected())[3]) - shown.position(), shown.forward()));
    orbit_ = OrbitCamera::fromCamera(shown, focus);
    freeResolved_ = orbit_.resolved();
    free_ = true;
    freeChanged_ = true;
}

void ViewportPanel::frameSelection(EditorState& state) {
    useFreeCamera(state);
    Aabb box;
    for (const NodeOverlay& o : overlays(state))
        if (state.selected() < 0 || o.node == state.selected()) {
            box.extend(o.box);
            box.extend(o.position);
        }
    if (box.empty()) return;
    orbit_.frame(box);
    freeResolved_ = orbit_.resolved();
    freeChanged_ = true;
}

// Bounds and icons change only with what the viewport shows: gathered once per revision, not per UI frame.
const std::vector<NodeOverlay>& ViewportPanel::overlays(EditorState& state) {
    if (overlaysRevision_ != state.revision()) {
        overlays_ = collectOverlays(state.session());
        overlaysRevision_ = state.revision();
    }
    return overlays_;
}

glm::dvec3 ViewportPanel::pointAhead(EditorState& state, double distance) const {
    if (renderedRevision_ == ~0ull && !free_) return glm::dvec3(0.0);  // nothing shown yet
    const assets::ResolvedCamera camera = shownCamera(state);
    return camera.position() + distance * camera.forward();
}

assets::ResolvedCamera ViewportPanel::shownCamera(EditorState& state) const {
    if (free_) return freeResolved_;
    return state.session().app().resource<render::RendererState>().lastInput.camera;
}

void ViewportPanel::render(EditorState& state, bool force) {
    const glm::ivec2 size = fixedSize_ ? *fixedSize_ : size_;
    if (!force && state.revision() == renderedRevision_ && size == renderedSize_ && !freeChanged_) return;
    auto& request = state.session().app().resource<render::RenderRequest>();
    request.cameraOverride = free_ ? std::optional(freeResolved_) : std::nullopt;
    // Per-pass timing synchronises after every pass, which costs llvmpipe its overlap: one frame in
    // kTimedEvery is timed per pass, the others only as a whole.
    const bool timed = frames_ % kTimedEvery == 1;  // not the first: plugins register their passes during it
    if (timed) timer_.clear();
    request.timer = timed ? &timer_ : nullptr;
    glFinish();
    const auto start = std::chrono::steady_clock::now();
    try {
        state.session().renderFrame(size.x, size.y, sceneCamera_);
    } catch (const InputError&) {
        sceneCamera_.clear();  // the camera it looked through was renamed or deleted
        state.session().renderFrame(size.x, size.y, sceneCamera_);
    }
    if (!display_) display_ = std::make_unique<ViewportDisplay>();
    display_->encode(state.session().app().resource<render::RendererState>().renderer->output());
    glFinish();
    lastFrameMs_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    request.timer = nullptr;
    imageStale_ = true;
    renderedRevision_ = state.revision();
    renderedSize_ = size;
    freeChanged_ = false;
    ++frames_;
}

const assets::RgbImage& ViewportPanel::image(EditorState& state) {
    if (imageStale_ && renderedSize_.x > 0) {
        image_ = state.session().app().resource<render::RendererState>().renderer->readOutput();
        imageStale_ = false;
    }
    return image_;
}

// The heat map is see-through where the error is small, so the render shows under it.
void ViewportPanel::uploadHeat(const assets::RgbImage& heat) {
    if (!heatTexture_ || heatTexture_.desc().width != heat.width || heatTexture_.desc().height != heat.height)
        heatTexture_ = gpu::Texture({.format = GL_RGBA8, .width = heat.width, .height = heat.height});
    std::vector<std::uint8_t> pixels(heat.pixelCount() * 4);
    for (std::size_t i = 0; i < heat.pixelCount(); ++i) {
        const float r = heat.rgb[3 * i], g = heat.rgb[3 * i + 1], b = heat.rgb[3 * i + 2];
        pixels[4 * i] = static_cast<std::uint8_t>(255.0f * r);
        pixels[4 * i + 1] = static_cast<std::uint8_t>(255.0f * g);
        pixels[4 * i + 2] = static_cast<std::uint8_t>(255.0f * b);
        pixels[4 * i + 3] = static_cast<std::uint8_t>(200.0f * std::min(1.0f, std::max({r, g, b})));
    }
    glTextureSubImage2D(heatTexture_.id(), 0, 0, 0, heat.width, heat.height, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
}

std::optional<std::string> ViewportPanel::draw(EditorState& state, ReferenceSnapshot& snapshot) {
    int mode = static_cast<int>(gizmoMode);
    ImGui::RadioButton("Move (W)", &mode, static_cast<int>(GizmoMode::Translate));
    ImGui::SameLine();
    ImGui::RadioButton("Rotate (E)", &mode, static_cast<int>(GizmoMode::Rotate));
    ImGui::SameLine();
    ImGui::RadioButton("Scale (R)", &mode, static_cast<int>(GizmoMode::Scale));
    gizmoMode = static_cast<GizmoMode>(mode);
    ImGui::SameLine();
    ImGui::Checkbox("Bounds", &showBounds);
    ImGui::SameLine();
    ImGui::Checkbox("Error", &showHeatMap);
    ImGui::SameLine();
    if (ImGui::Button("Frame (F)")) frameSelection(state);
    ImGui::SameLine();
    ImGui::TextDisabled("%s", free_ ? "free camera: RMB orbit, MMB pan, wheel zoom" : ("through " + shownCamera(state).name).c_str());

    const ImVec2 avail = ImGui::GetContentRegionAvail();
    if (!fixedSize_) size_ = glm::max(glm::ivec2(static_cast<int>(avail.x), static_cast<int>(avail.y)), glm::ivec2(16));
    const ImVec2 cursor = ImGui::GetCursorScreenPos();
    const glm::dvec2 origin(cursor.x, cursor.y);
    if (!display_) return std::nullopt;
    const ImVec2 shown(static_cast<float>(renderedSize_.x), static_cast<float>(renderedSize_.y));
    ImGui::Image(textureId(display_->display()), shown);
    const bool hovered = ImGui::IsItemHovered();
    const auto* result = snapshot.result();
    if (showHeatMap && result && snapshot.revision() == state.revision() && result->heat.width == renderedSize_.x &&
        result->heat.height == renderedSize_.y) {
        if (heatRevision_ != snapshot.revision()) uploadHeat(result->heat), heatRevision_ = snapshot.revision();
        ImGui::GetWindowDrawList()->AddImage(textureId(heatTexture_), cursor, ImVec2(cursor.x + shown.x, cursor.y + shown.y));
    }
    drawOverlays(state, origin);
    bool gizmoHovered = false;
    auto refused = handleGizmo(state, origin, gizmoHovered);
    handleCamera(state, hovered);
    if (hovered && !gizmoHovered && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
        const ImVec2 mouse = ImGui::GetIO().MousePos;
        pickAt(state, glm::dvec2(mouse.x, mouse.y) - origin);
    }
    if (hovered && !ImGui::GetIO().WantTextInput) {  // ImGui 1.86 indexes keys by the GLFW backend's key codes
        if (ImGui::IsKeyPressed(GLFW_KEY_W)) gizmoMode = GizmoMode::Translate;
        if (ImGui::IsKeyPressed(GLFW_KEY_E)) gizmoMode = GizmoMode::Rotate;
        if (ImGui::IsKeyPressed(GLFW_KEY_R)) gizmoMode = GizmoMode::Scale;
        if (ImGui::IsKeyPressed(GLFW_KEY_F)) frameSelection(state);
    }
    return refused;
}

void ViewportPanel::handleCamera(EditorState& state, bool hovered) {
    const ImGuiIO& io = ImGui::GetIO();
    const bool orbiting = ImGui::IsMouseDragging(ImGuiMouseButton_Right) && hovered;
    const bool panning = ImGui::IsMouseDragging(ImGuiMouseButton_Middle) && hovered;
    const bool zooming = hovered && io.MouseWheel != 0.0f;
    if (!orbiting && !panning && !zooming) return;
    useFreeCamera(state);
    if (orbiting) orbit_.orbit(io.MouseDelta.x, io.MouseDelta.y);
    if (panning) orbit_.pan(io.MouseDelta.x, io.MouseDelta.y, renderedSize_.y);
    if (zooming) orbit_.zoom(io.MouseWheel);
    freeResolved_ = orbit_.resolved();
    freeChanged_ = true;
}

std::optional<std::string> ViewportPanel::handleGizmo(EditorState& state, glm::dvec2 origin, bool& gizmoHovered) {
    const int node = state.selected();
    if (node < 0 || static_cast<std::size_t>(node) >= state.session().scene().nodes.size()) return std::nullopt;
    const assets::Node& rest = state.session().scene().nodes[static_cast<std::size_t>(node)];
    const glm::dmat4 parent = parentWorld(state.session(), node);
    const LocalTransform local = restPose(rest);
    const GizmoResult r = gizmo(gizmo_, gizmoMode, shownCamera(state), origin, renderedSize_.x, renderedSize_.y, parent, local,
                                ImGui::GetWindowDrawList());
    gizmoHovered = r.hovered || gizmo_.dragging || r.released;
    if (r.changed) {
        previewTransform(state.session(), node, parent * compose(r.local));
        freeChanged_ = true;  // re-render the preview
    }
    if (!r.released) return std::nullopt;
    try {
        state.set(transformEdits(node, r.local, rest.hasMatrix), gizmoMode == GizmoMode::Translate ? "move" : gizmoMode == GizmoMode::Rotate ? "rotate" : "scale");
    } catch (const InputError& e) {
        freeChanged_ = true;  // the preview moved the entity: show the state as it is
        return e.what();
    }
    return std::nullopt;
}

void ViewportPanel::drawOverlays(EditorState& state, glm::dvec2 origin) {
    if (!showBounds) return;
    const assets::ResolvedCamera camera = shownCamera(state);
    ImDrawList* list = ImGui::GetWindowDrawList();
    for (const NodeOverlay& o : overlays(state)) {
        const bool selected = o.node == state.selected();
        const unsigned colour = selected ? IM_COL32(255, 200, 60, 255) : IM_COL32(120, 200, 255, 140);
        if (o.kind == OverlayKind::Media || (selected && o.kind == OverlayKind::Mesh))
            drawBox(list, camera, origin, renderedSize_.x, renderedSize_.y, o.box, colour);
        if (o.kind == OverlayKind::Light)
            drawLightIcon(list, camera, origin, renderedSize_.x, renderedSize_.y, o.position, o.direction, o.directional, colour);
    }
}

void ViewportPanel::pickAt(EditorState& state, glm::dvec2 pixel) {
    const assets::ResolvedCamera camera = shownCamera(state);
    std::vector<PickTarget> targets;
    for (const NodeOverlay& o : overlays(state)) {
        PickTarget t{o.node, o.box};
        if (o.kind == OverlayKind::Light || o.kind == OverlayKind::Camera) {
            t.sphere = true;
            t.centre = o.position;
            t.radius = 0.04 * std::max(glm::length(o.position - camera.position()), 0.1);  // an icon-sized ball
        }
        targets.push_back(t);
    }
    state.select(pick(viewportRay(camera, pixel, renderedSize_.x, renderedSize_.y), targets));
}

}  // namespace nimbus::sandbox::editor
