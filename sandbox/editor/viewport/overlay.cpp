// The viewport's overlays that are not the gizmo: selection boxes and light icons (declared in gizmo.h).
#include <algorithm>
#include <array>
#include <cmath>

#include <glm/gtc/constants.hpp>
#include <imgui.h>

#include "nimbus/base/camera_frame.h"
#include "viewport/gizmo.h"
#include "viewport/draw_list_points.h"
#include "viewport/picking.h"

namespace nimbus::sandbox::editor {
namespace {

constexpr double kLightIconPixels = 7.0;

// Liang-Barsky: keeps the part of a screen segment inside [lo, hi], so far-off ends keep float precision.
bool clipToRect(glm::dvec2& a, glm::dvec2& b, glm::dvec2 lo, glm::dvec2 hi) {
    double t0 = 0.0, t1 = 1.0;
    const glm::dvec2 d = b - a;
    for (int axis = 0; axis < 2; ++axis) {
        const std::array<std::array<double, 2>, 2> sides{{{-d[axis], a[axis] - lo[axis]}, {d[axis], hi[axis] - a[axis]}}};
        for (const auto& [p, q] : sides) {
            if (p == 0.0) {
                if (q < 0.0) return false;
                continue;
            }
            if (p < 0.0) t0 = std::max(t0, q / p);
            else t1 = std::min(t1, q / p);
        }
    }
    if (!(t0 <= t1)) return false;
    const glm::dvec2 start = a;
    a = start + t0 * d;
    b = start + t1 * d;
    return true;
}

// A world segment cut at the near plane (never wrapped around behind the camera), then to the screen.
void drawWorldSegment(ImDrawList* drawList, const assets::ResolvedCamera& camera, glm::dvec2 origin, int width,
                      int height, glm::dvec3 a, glm::dvec3 b, unsigned colour, float thickness) {
    const double nearPlane = std::max(camera.params.znear, 1e-9);
    const double da = viewDepth(camera, a), db = viewDepth(camera, b);
    if (!(da >= nearPlane) && !(db >= nearPlane)) return;
    if (!(da >= nearPlane)) a += (b - a) * ((nearPlane - da) / (db - da));
    else if (!(db >= nearPlane)) b += (a - b) * ((nearPlane - db) / (da - db));
    const auto pa = projectToViewport(camera, a, width, height), pb = projectToViewport(camera, b, width, height);
    if (!pa || !pb) return;
    glm::dvec2 p0 = *pa, p1 = *pb;
    const glm::dvec2 size(std::max(1, width), std::max(1, height));
    if (!clipToRect(p0, p1, -size, 2.0 * size)) return;
    drawList->AddLine(toImVec(origin, p0), toImVec(origin, p1), colour, thickness);
}

}  // namespace

void drawBox(ImDrawList* drawList, const assets::ResolvedCamera& camera, glm::dvec2 origin, int width, int height,
             const Aabb& box, unsigned colour) {
    if (!drawList || box.empty()) return;
    const auto corner = [&](int i) {
        return glm::dvec3((i & 1) ? box.max.x : box.min.x, (i & 2) ? box.max.y : box.min.y, (i & 4) ? box.max.z : box.min.z);
    };
    for (int i = 0; i < 8; ++i) {
        for (int bit = 1; bit < 8; bit <<= 1) {
            if (!(i & bit)) drawWorldSegment(drawList, camera, origin, width, height, corner(i), corner(i | bit), colour, 1.5f);
        }
    }
}

void drawLightIcon(ImDrawList* drawList, const assets::ResolvedCamera& camera, glm::dvec2 origin, int width, int height,
                   const glm::dvec3& position, const glm::dvec3& direction, bool directional, unsigned colour) {
    const auto centre = projectToViewport(camera, position, width, height);
    if (!drawList || !centre) return;
    const auto r = static_cast<float>(kLightIconPixels);
    drawList->AddCircleFilled(toImVec(origin, *centre), r, colour);
    if (directional) {
        // An arrow about six icon radii long on screen, along the direction the light travels.
        const double length = 6.0 * kLightIconPixels * worldPerPixel(camera, viewDepth(camera, position), height);
        const glm::dvec3 tip = position + unitOr(direction, {0.0, 0.0, -1.0}) * length;
        drawWorldSegment(drawList, camera, origin, width, height, position, tip, colour, 2.0f);
        if (const auto tipPx = projectToViewport(camera, tip, width, height))
            drawList->AddCircleFilled(toImVec(origin, *tipPx), 0.5f * r, colour);
        return;
    }
    for (int i = 0; i < 8; ++i) {
        const double angle = glm::pi<double>() * i / 4.0;
        const glm::dvec2 dir(std::cos(angle), std::sin(angle));
        drawList->AddLine(toImVec(origin, *centre + dir * (kLightIconPixels + 2.0)),
                          toImVec(origin, *centre + dir * (kLightIconPixels + 6.0)), colour, 1.5f);
    }
}

}  // namespace nimbus::sandbox::editor
