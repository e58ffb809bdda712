#include "viewport/gizmo.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>

#include <glm/gtc/constants.hpp>
#include <imgui.h>

#include "nimbus/base/camera_frame.h"
#include "viewport/draw_list_points.h"
#include "viewport/picking.h"

namespace nimbus::sandbox::editor {
namespace {

constexpr double kHitTolerancePixels = 8.0;
constexpr double kMinAxisFraction = 0.2;  // an axis foreshortened below this (of its size) points at the camera
constexpr int kRingSegments = 64;
constexpr double kEdgeOnPenaltyPixels = 6.0;
constexpr double kMinScaleRatio = 1e-3;

// Where the gizmo is: its world centre, the world length of a handle and the handles' world directions.
struct GizmoFrame {
    glm::dvec3 centre{0.0};
    double length = 0.0;
    std::array<glm::dvec3, 3> axes{};
};

struct ScreenAxis {
    glm::dvec2 centre{0.0}, tip{0.0};
};

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

std::optional<GizmoFrame> gizmoFrame(GizmoMode mode, const assets::ResolvedCamera& camera, int height,
                                     const glm::dmat4& nodeWorld, double sizePixels) {
    GizmoFrame f;
    f.centre = glm::dvec3(nodeWorld[3]);
    f.length = sizePixels * worldPerPixel(camera, viewDepth(camera, f.centre), height);
    if (!finite(f.centre) || !(f.length > 0.0) || !std::isfinite(f.length)) return std::nullopt;
    // Scale works along the node's own axes (its scale is local); the others along the world axes.
    const glm::dmat3 rotation =
        mode == GizmoMode::Scale ? glm::mat3_cast(decompose(nodeWorld).rotation) : glm::dmat3(1.0);
    for (int i = 0; i < 3; ++i) f.axes[static_cast<size_t>(i)] = rotation[i];
    return f;
}

std::optional<ScreenAxis> screenAxis(const GizmoFrame& f, int axis, const assets::ResolvedCamera& camera, int width,
                                     int height, double sizePixels) {
    const auto centre = projectToViewport(camera, f.centre, width, height);
    const auto tip = projectToViewport(camera, f.centre + f.axes[static_cast<size_t>(axis)] * f.length, width, height);
    if (!centre || !tip || glm::length(*tip - *centre) < kMinAxisFraction * sizePixels) return std::nullopt;
    return ScreenAxis{*centre, *tip};
}

// The rotate handle of `axis`: a circle about it, as projected points (nullopt behind the camera).
std::array<std::optional<glm::dvec2>, kRingSegments> ring(const GizmoFrame& f, int axis,
                                                          const assets::ResolvedCamera& camera, int width, int height) {
    const glm::dvec3 u = f.axes[static_cast<size_t>((axis + 1) % 3)], v = f.axes[static_cast<size_t>((axis + 2) % 3)];
    std::array<std::optional<glm::dvec2>, kRingSegments> points;
    for (int i = 0; i < kRingSegments; ++i) {
        const double angle = 2.0 * glm::pi<double>() * i / kRingSegments;
        const glm::dvec3 p = f.centre + f.length * (std::cos(angle) * u + std::sin(angle) * v);
        points[static_cast<size_t>(i)] = projectToViewport(camera, p, width, height);
    }
    return points;
}

// How face-on a ring is: 1 when its axis points at the camera, 0 seen edge-on.
double ringOpenness(const GizmoFrame& f, int axis, const assets::ResolvedCamera& camera) {
    const glm::dvec3 view = camera.params.projection == assets::Projection::Orthographic
                                ? camera.forward()
                                : unitOr(f.centre - camera.position(), camera.forward());
    return std::abs(glm::dot(view, f.axes[static_cast<size_t>(axis)]));
}

double segmentDistance(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b) {
    const glm::dvec2 ab = b - a;
    const double lengthSquared = glm::dot(ab, ab);
    const double t = lengthSquared > 0.0 ? std::clamp(glm::dot(p - a, ab) / lengthSquared, 0.0, 1.0) : 0.0;
    return glm::length(p - (a + t * ab));
}

double ringDistance(const std::array<std::optional<glm::dvec2>, kRingSegments>& points, glm::dvec2 mouse) {
    double best = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < points.size(); ++i) {
        const auto& a = points[i];
        const auto& b = points[(i + 1) % points.size()];
        if (a && b) best = std::min(best, segmentDistance(mouse, *a, *b));
    }
    return best;
}

// Counter-clockwise angle on screen (y down) from `a` to `b` around `centre`; nullopt on the centre.
std::optional<double> sweptAngle(glm::dvec2 centre, glm::dvec2 a, glm::dvec2 b) {
    const glm::dvec2 v0 = a - centre, v1 = b - centre;
    if (!(glm::length(v0) > 1e-9) || !(glm::length(v1) > 1e-9)) return std::nullopt;
    return std::atan2(-(v0.x * v1.y - v0.y * v1.x), glm::dot(v0, v1));
}

// Parameter along the line c + s·a of its closest point to the ray; nullopt when parallel or behind the camera.
std::optional<double> closestOnLine(const Ray& ray, const glm::dvec3& c, const glm::dvec3& a) {
    const glm::dvec3 w = ray.origin - c;
    const double dd = glm::dot(ray.direction, ray.direction), aa = glm::dot(a, a), b = glm::dot(a, ray.direction);
    const double denominator = aa * dd - b * b;
    if (!(denominator > 1e-12 * aa * dd)) return std::nullopt;
    const double s = (dd * glm::dot(a, w) - b * glm::dot(ray.direction, w)) / denominator;
    const double t = (b * s - glm::dot(ray.direction, w)) / dd;
    if (!(t > 0.0) || !std::isfinite(s)) return std::nullopt;
    return s;
}

// The parent's linear part, when it can be inverted.
std::optional<glm::dmat3> parentLinear(const glm::dmat4& parentWorld) {
    const glm::dmat3 linear(parentWorld);
    const double det = glm::determinant(linear);
    if (!(std::abs(det) > 1e-300) || !std::isfinite(det)) return std::nullopt;
    return linear;
}

std::optional<LocalTransform> dragTranslate(int axis, const assets::ResolvedCamera& camera, int width, int height,
                                            const glm::dmat4& parentWorld, const LocalTransform& start,
                                            glm::dvec2 startMouse, glm::dvec2 mouse) {
    const glm::dmat4 nodeWorld = parentWorld * compose(start);
    const auto f = gizmoFrame(GizmoMode::Translate, camera, height, nodeWorld, kGizmoSizePixels);
    const auto linear = parentLinear(parentWorld);
    if (!f || !linear || !screenAxis(*f, axis, camera, width, height, kGizmoSizePixels)) return std::nullopt;
    const glm::dvec3 a = f->axes[static_cast<size_t>(axis)];
    const auto s0 = closestOnLine(viewportRay(camera, startMouse, width, height), f->centre, a);
    const auto s1 = closestOnLine(viewportRay(camera, mouse, width, height), f->centre, a);
    if (!s0 || !s1) return std::nullopt;
    LocalTransform out = start;
    out.translation += glm::inverse(*linear) * (a * (*s1 - *s0));
    return finite(out.translation) ? std::optional<LocalTransform>(out) : std::nullopt;
}

std::optional<LocalTransform> dragRotate(int axis, const assets::ResolvedCamera& camera, int width, int height,
                                         const glm::dmat4& parentWorld, const LocalTransform& start,
                                         glm::dvec2 startMouse, glm::dvec2 mouse) {
    const glm::dvec3 centre = glm::dvec3((parentWorld * compose(start))[3]);
    const auto centrePx = projectToViewport(camera, centre, width, height);
    const auto linear = parentLinear(parentWorld);
    if (!centrePx || !linear) return std::nullopt;
    const auto swept = sweptAngle(*centrePx, startMouse, mouse);
    if (!swept) return std::nullopt;
    glm::dvec3 a(0.0);
    a[axis] = 1.0;
    // Counter-clockwise on screen is counter-clockwise about an axis that points at the viewer.
    const glm::dvec3 toCamera = camera.params.projection == assets::Projection::Orthographic
                                    ? -camera.forward()
                                    : camera.position() - centre;
    const double angle = glm::dot(a, toCamera) >= 0.0 ? *swept : -*swept;
    // The world rotation about `a` seen from the parent's space (a mirrored parent turns the other way).
    const double mirror = glm::determinant(*linear) < 0.0 ? -1.0 : 1.0;
    const glm::dvec3 parentAxis = mirror * unitOr(glm::inverse(*linear) * a, a);
    LocalTransform out = start;
    out.rotation = glm::normalize(glm::angleAxis(angle, parentAxis) * start.rotation);
    return out;
}

std::optional<LocalTransform> dragScale(int axis, const assets::ResolvedCamera& camera, int width, int height,
                                        const glm::dmat4& parentWorld, const LocalTransform& start,
                                        glm::dvec2 startMouse, glm::dvec2 mouse) {
    const auto f = gizmoFrame(GizmoMode::Scale, camera, height, parentWorld * compose(start), kGizmoSizePixels);
    if (!f) return std::nullopt;
    const auto screen = screenAxis(*f, axis, camera, width, height, kGizmoSizePixels);
    if (!screen) return std::nullopt;
    const glm::dvec2 u = glm::normalize(screen->tip - screen->centre);
    const double d0 = glm::dot(startMouse - screen->centre, u), d1 = glm::dot(mouse - screen->centre, u);
    if (!(std::abs(d0) > 1e-6)) return std::nullopt;
    double ratio = d1 / d0;
    if (std::abs(ratio) < kMinScaleRatio) ratio = std::copysign(kMinScaleRatio, ratio);
    LocalTransform out = start;
    out.scale[axis] *= ratio;
    return std::isfinite(out.scale[axis]) ? std::optional<LocalTransform>(out) : std::nullopt;
}

std::optional<LocalTransform> drag(GizmoMode mode, int axis, const assets::ResolvedCamera& camera, int width,
                                   int height, const glm::dmat4& parentWorld, const LocalTransform& start,
                                   glm::dvec2 startMouse, glm::dvec2 mouse) {
    if (axis < 0 || axis > 2) return std::nullopt;
    switch (mode) {
        case GizmoMode::Translate: return dragTranslate(axis, camera, width, height, parentWorld, start, startMouse, mouse);
        case GizmoMode::Rotate: return dragRotate(axis, camera, width, height, parentWorld, start, startMouse, mouse);
        case GizmoMode::Scale: return dragScale(axis, camera, width, height, parentWorld, start, startMouse, mouse);
    }
    return std::nullopt;
}

bool sameTransform(const LocalTransform& a, const LocalTransform& b) {
    return a.translation == b.translation && a.rotation == b.rotation && a.scale == b.scale;
}

}  // namespace

LocalTransform decompose(const glm::dmat4& local) {
    LocalTransform t;
    t.translation = glm::dvec3(local[3]);
    glm::dvec3 c0(local[0]);
    const glm::dvec3 c1(local[1]), c2(local[2]);
    const bool mirrored = glm::determinant(glm::dmat3(local)) < 0.0;
    if (mirrored) c0 = -c0;
    // Gram-Schmidt with fallbacks, so zero scales still give a rotation.
    const glm::dvec3 r0 = unitOr(c0, unitOr(glm::cross(c1, c2), {1.0, 0.0, 0.0}));
    const glm::dvec3 helper = std::abs(r0.y) < 0.9 ? glm::dvec3(0.0, 1.0, 0.0) : glm::dvec3(1.0, 0.0, 0.0);
    const glm::dvec3 c1Perp = c1 - glm::dot(c1, r0) * r0;
    const glm::dvec3 r1 = unitOr(c1Perp, unitOr(glm::cross(c2, r0), glm::normalize(helper - glm::dot(helper, r0) * r0)));
    const glm::dvec3 r2 = glm::cross(r0, r1);
    t.rotation = glm::normalize(glm::quat_cast(glm::dmat3(r0, r1, r2)));
    t.scale = {glm::length(c0) * (mirrored ? -1.0 : 1.0), glm::length(c1), glm::length(c2)};
    return t;
}

glm::dmat4 compose(const LocalTransform& t) {
    const glm::dmat3 r = glm::mat3_cast(t.rotation);
    glm::dmat4 m(1.0);
    for (int i = 0; i < 3; ++i) m[i] = glm::dvec4(r[i] * t.scale[i], 0.0);
    m[3] = glm::dvec4(t.translation, 1.0);
    return m;
}

int hitGizmo(GizmoMode mode, const assets::ResolvedCamera& camera, int width, int height, const glm::dmat4& nodeWorld,
             glm::dvec2 mouse, double sizePixels) {
    const auto f = gizmoFrame(mode, camera, height, nodeWorld, sizePixels);
    if (!f) return -1;
    int best = -1;
    double bestScore = std::numeric_limits<double>::infinity();
    for (int axis = 0; axis < 3; ++axis) {
        double distance = std::numeric_limits<double>::infinity(), score = distance;
        if (mode == GizmoMode::Rotate) {
            distance = ringDistance(ring(*f, axis, camera, width, height), mouse);
            // A ring seen edge-on is a line through the others: where they cross, the open ring wins.
            score = distance + kEdgeOnPenaltyPixels * (1.0 - ringOpenness(*f, axis, camera));
        } else if (const auto screen = screenAxis(*f, axis, camera, width, height, sizePixels)) {
            distance = segmentDistance(mouse, screen->centre, screen->tip);
            score = distance;
        }
        if (distance < kHitTolerancePixels && score < bestScore) {
            bestScore = score;
            best = axis;
        }
    }
    return best;
}

LocalTransform dragGizmo(GizmoMode mode, int axis, const assets::ResolvedCamera& camera, int width, int height,
                         const glm::dmat4& parentWorld, const LocalTransform& startLocal, glm::dvec2 startMouse,
                         glm::dvec2 mouse) {
    return drag(mode, axis, camera, width, height, parentWorld, startLocal, startMouse, mouse).value_or(startLocal);
}

namespace {

constexpr float kHandleThickness = 3.0f;

unsigned axisColour(int axis, bool highlighted) {
    if (highlighted) return IM_COL32(255, 215, 64, 255);
    constexpr std::array<unsigned, 3> colours{IM_COL32(230, 70, 70, 255), IM_COL32(100, 200, 80, 255),
                                              IM_COL32(80, 130, 240, 255)};
    return colours[static_cast<size_t>(axis)];
}

void drawHandle(ImDrawList* drawList, GizmoMode mode, const ScreenAxis& s, glm::dvec2 origin, unsigned colour) {
    drawList->AddLine(toImVec(origin, s.centre), toImVec(origin, s.tip), colour, kHandleThickness);
    const glm::dvec2 dir = glm::normalize(s.tip - s.centre), side(-dir.y, dir.x);
    if (mode == GizmoMode::Translate) {
        drawList->AddTriangleFilled(toImVec(origin, s.tip + 12.0 * dir), toImVec(origin, s.tip + 6.0 * side),
                                    toImVec(origin, s.tip - 6.0 * side), colour);
    } else {
        drawList->AddRectFilled(toImVec(origin, s.tip - glm::dvec2(5.0)), toImVec(origin, s.tip + glm::dvec2(5.0)), colour);
    }
}

void drawGizmo(ImDrawList* drawList, GizmoMode mode, const assets::ResolvedCamera& camera, glm::dvec2 origin, int width,
               int height, const glm::dmat4& nodeWorld, int highlight) {
    const auto f = gizmoFrame(mode, camera, height, nodeWorld, kGizmoSizePixels);
    if (!f || !drawList) return;
    for (int axis = 0; axis < 3; ++axis) {
        const unsigned colour = axisColour(axis, axis == highlight);
        if (mode == GizmoMode::Rotate) {
            const auto points = ring(*f, axis, camera, width, height);
            for (size_t i = 0; i < points.size(); ++i) {
                const auto& a = points[i];
                const auto& b = points[(i + 1) % points.size()];
                if (a && b) drawList->AddLine(toImVec(origin, *a), toImVec(origin, *b), colour, kHandleThickness - 0.5f);
            }
        } else if (const auto screen = screenAxis(*f, axis, camera, width, height, kGizmoSizePixels)) {
            drawHandle(drawList, mode, *screen, origin, colour);
        }
    }
    if (const auto centre = projectToViewport(camera, f->centre, width, height))
        drawList->AddCircleFilled(toImVec(origin, *centre), 4.0f, IM_COL32(240, 240, 240, 255));
}

// Rotation angles wrap at half a turn: past a quarter turn the drag restarts from where it is.
void rebaseRotation(GizmoState& state, const assets::ResolvedCamera& camera, int width, int height,
                    const glm::dmat4& parentWorld, glm::dvec2 mouse) {
    const glm::dvec3 centre = glm::dvec3((parentWorld * compose(state.startLocal))[3]);
    const auto centrePx = projectToViewport(camera, centre, width, height);
    if (!centrePx) return;
    const auto swept = sweptAngle(*centrePx, state.startMouse, mouse);
    if (swept && std::abs(*swept) > 0.5 * glm::pi<double>()) {
        state.startMouse = mouse;
        state.startLocal = state.current;
    }
}

void continueDrag(GizmoState& state, const assets::ResolvedCamera& camera, int width, int height,
                  const glm::dmat4& parentWorld, std::optional<glm::dvec2> mouse, const LocalTransform& local,
                  GizmoResult& result) {
    result.hovered = true;
    if (mouse) {
        // A degenerate frame (mouse ray parallel to the axis, ...) keeps the last good transform.
        if (const auto next = drag(state.mode, state.axis, camera, width, height, parentWorld, state.startLocal,
                                   state.startMouse, *mouse)) {
            state.current = *next;
            if (state.mode == GizmoMode::Rotate) rebaseRotation(state, camera, width, height, parentWorld, *mouse);
        }
    }
    result.local = state.current;
    result.changed = !sameTransform(state.current, local);
    const ImGuiIO& io = ImGui::GetIO();
    if (io.MouseReleased[0] || !io.MouseDown[0]) {
        result.released = true;
        state.dragging = false;
    }
}

}  // namespace

GizmoResult gizmo(GizmoState& state, GizmoMode mode, const assets::ResolvedCamera& camera, glm::dvec2 origin, int width,
                  int height, const glm::dmat4& parentWorld, const LocalTransform& local, ImDrawList* drawList) {
    const ImGuiIO& io = ImGui::GetIO();
    std::optional<glm::dvec2> mouse;
    if (ImGui::IsMousePosValid(&io.MousePos))
        mouse = glm::dvec2(static_cast<double>(io.MousePos.x), static_cast<double>(io.MousePos.y)) - origin;
    GizmoResult result;
    result.local = local;
    int highlight = -1;
    if (state.dragging) {
        continueDrag(state, camera, width, height, parentWorld, mouse, local, result);
        highlight = state.axis;
    } else {
        const bool inside = mouse && mouse->x >= 0.0 && mouse->y >= 0.0 && mouse->x < width && mouse->y < height;
        highlight = inside ? hitGizmo(mode, camera, width, height, parentWorld * compose(local), *mouse) : -1;
        result.hovered = highlight >= 0;
        if (result.hovered && io.MouseClicked[0]) {
            state = GizmoState{highlight, true, mode, *mouse, local, local, local};
        }
    }
    if (!state.dragging && !result.released) state.axis = -1;
    drawGizmo(drawList, state.dragging ? state.mode : mode, camera, origin, width, height,
              parentWorld * compose(result.local), highlight);
    return result;
}

}  // namespace nimbus::sandbox::editor
