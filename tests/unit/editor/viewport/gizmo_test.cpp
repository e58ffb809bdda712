// Tests sandbox/editor/viewport/gizmo.cpp: handle hit tests, drags, and the immediate-mode loop under ImGui.
#include "viewport/gizmo.h"

#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/constants.hpp>
#include <imgui.h>

#include "viewport/picking.h"
#include "viewport_test_util.h"

namespace nimbus::sandbox::editor {
namespace {

constexpr int kWidth = 800, kHeight = 600;
const glm::dvec2 kCentre(400.0, 300.0);

// Looking down -Z at the origin from 10 units: x is right, y is up, z points at the camera.
assets::ResolvedCamera frontCamera() { return testing::lookAt({0.0, 0.0, 10.0}, {0.0, 0.0, 0.0}, 0.8); }

double pixelsToWorld(double pixels) { return pixels * 2.0 * 10.0 * std::tan(0.4) / kHeight; }

void expectNear(const glm::dvec3& a, const glm::dvec3& b, double tolerance) {
    EXPECT_NEAR(glm::length(a - b), 0.0, tolerance) << "(" << a.x << ", " << a.y << ", " << a.z << ") vs (" << b.x
                                                    << ", " << b.y << ", " << b.z << ")";
}

TEST(GizmoTransform, DecomposeInvertsCompose) {
    LocalTransform t;
    t.translation = {1.0, -2.0, 3.0};
    t.rotation = glm::angleAxis(0.7, glm::normalize(glm::dvec3(1.0, 2.0, -0.5)));
    t.scale = {2.0, 0.5, 3.0};
    const LocalTransform back = decompose(compose(t));
    expectNear(back.translation, t.translation, 1e-12);
    expectNear(back.scale, t.scale, 1e-12);
    EXPECT_NEAR(std::abs(glm::dot(back.rotation, t.rotation)), 1.0, 1e-12);
    t.scale = {-1.0, 2.0, 2.0};  // mirrored
    const glm::dmat4 mirrored = compose(t);
    const glm::dmat4 again = compose(decompose(mirrored));
    for (int i = 0; i < 4; ++i) expectNear(glm::dvec3(again[i]), glm::dvec3(mirrored[i]), 1e-12);
    t.scale = {0.0, 0.0, 1.0};  // zero scale: a rotation still comes out
    const LocalTransform flat = decompose(compose(t));
    EXPECT_NEAR(glm::length(flat.rotation), 1.0, 1e-12);
    EXPECT_TRUE(testing::finite(flat.scale));
}

TEST(HitGizmo, FindsTheHandlesAndNothingFarAway) {
    const assets::ResolvedCamera camera = frontCamera();
    const glm::dmat4 node(1.0);
    const auto xTip = projectToViewport(camera, {pixelsToWorld(90.0), 0.0, 0.0}, kWidth, kHeight);
    ASSERT_TRUE(xTip.has_value());
    EXPECT_NEAR(xTip->x, kCentre.x + 90.0, 1e-9);
    EXPECT_EQ(hitGizmo(GizmoMode::Translate, camera, kWidth, kHeight, node, *xTip), 0);
    EXPECT_EQ(hitGizmo(GizmoMode::Translate, camera, kWidth, kHeight, node, kCentre + glm::dvec2(0.0, -80.0)), 1);
    EXPECT_EQ(hitGizmo(GizmoMode::Scale, camera, kWidth, kHeight, node, *xTip + glm::dvec2(2.0, 3.0)), 0);
    EXPECT_EQ(hitGizmo(GizmoMode::Translate, camera, kWidth, kHeight, node, {50.0, 50.0}), -1);
    EXPECT_EQ(hitGizmo(GizmoMode::Translate, camera, kWidth, kHeight, node, kCentre + glm::dvec2(200.0, 0.0)), -1);
    // The z ring faces the camera: a circle of 90 pixels.
    const glm::dvec2 onRing = kCentre + 90.0 * glm::dvec2(std::cos(0.6), -std::sin(0.6));
    EXPECT_EQ(hitGizmo(GizmoMode::Rotate, camera, kWidth, kHeight, node, onRing), 2);
    EXPECT_EQ(hitGizmo(GizmoMode::Rotate, camera, kWidth, kHeight, node, kCentre + glm::dvec2(30.0, 30.0)), -1);
    // The x ring is seen edge-on, as a vertical line: still hittable, but where it ends on the z ring, z wins.
    EXPECT_EQ(hitGizmo(GizmoMode::Rotate, camera, kWidth, kHeight, node, kCentre + glm::dvec2(0.0, -45.0)), 0);
    EXPECT_EQ(hitGizmo(GizmoMode::Rotate, camera, kWidth, kHeight, node, kCentre + glm::dvec2(0.0, -90.0)), 2);
}

TEST(HitGizmo, AnAxisPointingAtTheCameraIsNotHittable) {
    const assets::ResolvedCamera camera = frontCamera();
    for (double x = -20.0; x <= 20.0; x += 2.0)
        for (double y = -20.0; y <= 20.0; y += 2.0)
            EXPECT_NE(hitGizmo(GizmoMode::Translate, camera, kWidth, kHeight, glm::dmat4(1.0), kCentre + glm::dvec2(x, y)), 2);
    LocalTransform start;
    const LocalTransform moved = dragGizmo(GizmoMode::Translate, 2, camera, kWidth, kHeight, glm::dmat4(1.0), start,
                                           kCentre, kCentre + glm::dvec2(40.0, 10.0));
    EXPECT_EQ(moved.translation, start.translation);
}

TEST(DragGizmo, TranslateFollowsTheMouseAlongTheAxis) {
    const assets::ResolvedCamera camera = frontCamera();
    LocalTransform start;
    start.scale = {3.0, 1.0, 1.0};  // the node's own scale does not matter
    const glm::dvec2 grab = kCentre + glm::dvec2(80.0, 0.0);
    const LocalTransform moved = dragGizmo(GizmoMode::Translate, 0, camera, kWidth, kHeight, glm::dmat4(1.0), start, grab,
                                           grab + glm::dvec2(50.0, 0.0));
    expectNear(moved.translation, {pixelsToWorld(50.0), 0.0, 0.0}, 1e-9);
    // Under a parent scaled by 2 the same world move is half as many local units.
    const glm::dmat4 parent = glm::scale(glm::dmat4(1.0), glm::dvec3(2.0));
    const LocalTransform half =
        dragGizmo(GizmoMode::Translate, 0, camera, kWidth, kHeight, parent, start, grab, grab + glm::dvec2(50.0, 0.0));
    expectNear(half.translation, {0.5 * pixelsToWorld(50.0), 0.0, 0.0}, 1e-9);
}

TEST(DragGizmo, TranslateUnderARotatedParentMovesAlongTheWorldAxis) {
    const assets::ResolvedCamera camera = testing::lookAt({3.0, 4.0, 10.0}, {1.0, 0.0, 0.0}, 0.8);
    glm::dmat4 parent = glm::translate(glm::dmat4(1.0), glm::dvec3(1.0, 0.0, 0.0));
    parent = glm::rotate(parent, 0.9, glm::dvec3(0.0, 0.0, 1.0));
    parent = glm::scale(parent, glm::dvec3(1.5));
    LocalTransform start;
    const glm::dvec3 centre(parent[3]);
    const glm::dvec3 target = centre + glm::dvec3(0.0, 0.7, 0.0);
    const auto from = projectToViewport(camera, centre + glm::dvec3(0.0, 0.2, 0.0), kWidth, kHeight);
    const auto to = projectToViewport(camera, target, kWidth, kHeight);
    ASSERT_TRUE(from && to);
    const LocalTransform moved = dragGizmo(GizmoMode::Translate, 1, camera, kWidth, kHeight, parent, start, *from, *to);
    expectNear(glm::dvec3((parent * compose(moved))[3]), centre + glm::dvec3(0.0, 0.5, 0.0), 1e-9);
}

TEST(DragGizmo, RotateByAQuarterTurnOfTheMouse) {
    const assets::ResolvedCamera camera = frontCamera();
    const LocalTransform start;
    // Right of the centre to above it: counter-clockwise on screen, about +z which points at the camera.
    const LocalTransform turned = dragGizmo(GizmoMode::Rotate, 2, camera, kWidth, kHeight, glm::dmat4(1.0), start,
                                            kCentre + glm::dvec2(90.0, 0.0), kCentre + glm::dvec2(0.0, -60.0));
    expectNear(turned.rotation * glm::dvec3(1.0, 0.0, 0.0), {0.0, 1.0, 0.0}, 1e-12);
    EXPECT_NEAR(glm::angle(turned.rotation), 0.5 * glm::pi<double>(), 1e-12);
    expectNear(turned.translation, start.translation, 0.0);
    // Seen from behind, the same mouse motion turns the other way about +z.
    const assets::ResolvedCamera back = testing::lookAt({0.0, 0.0, -10.0}, {0.0, 0.0, 0.0}, 0.8);
    const LocalTransform other = dragGizmo(GizmoMode::Rotate, 2, back, kWidth, kHeight, glm::dmat4(1.0), start,
                                           kCentre + glm::dvec2(90.0, 0.0), kCentre + glm::dvec2(0.0, -60.0));
    expectNear(other.rotation * glm::dvec3(1.0, 0.0, 0.0), {0.0, -1.0, 0.0}, 1e-12);
}

TEST(DragGizmo, ScaleByTheRatioOfDistancesAlongTheAxis) {
    const assets::ResolvedCamera camera = frontCamera();
    LocalTransform start;
    start.scale = {1.5, 2.0, 1.0};
    const LocalTransform scaled = dragGizmo(GizmoMode::Scale, 0, camera, kWidth, kHeight, glm::dmat4(1.0), start,
                                            kCentre + glm::dvec2(90.0, 0.0), kCentre + glm::dvec2(180.0, 4.0));
    expectNear(scaled.scale, {3.0, 2.0, 1.0}, 1e-12);
}

TEST(DragGizmo, DegenerateInputStaysFinite) {
    LocalTransform start;
    start.translation = {0.0, 0.0, 10.0};  // on the camera
    for (const GizmoMode mode : {GizmoMode::Translate, GizmoMode::Rotate, GizmoMode::Scale}) {
        EXPECT_EQ(hitGizmo(mode, frontCamera(), kWidth, kHeight, compose(start), kCentre), -1);
        for (int axis = 0; axis < 3; ++axis) {
            const LocalTransform out = dragGizmo(mode, axis, frontCamera(), kWidth, kHeight, glm::dmat4(1.0), start,
                                                 kCentre, kCentre + glm::dvec2(10.0, 5.0));
            EXPECT_EQ(out.translation, start.translation);
            EXPECT_EQ(out.scale, start.scale);
        }
    }
    LocalTransform flat;
    flat.scale = glm::dvec3(0.0);
    const glm::dmat4 zero = glm::scale(glm::dmat4(1.0), glm::dvec3(0.0));
    for (const GizmoMode mode : {GizmoMode::Translate, GizmoMode::Rotate, GizmoMode::Scale}) {
        EXPECT_GE(hitGizmo(mode, frontCamera(), kWidth, kHeight, compose(flat), kCentre + glm::dvec2(60.0, 0.0)), -1);
        const LocalTransform out = dragGizmo(mode, 0, frontCamera(), kWidth, kHeight, zero, flat,
                                             kCentre + glm::dvec2(60.0, 0.0), kCentre + glm::dvec2(90.0, 0.0));
        EXPECT_TRUE(testing::finite(out.translation) && testing::finite(out.scale));
    }
}

// One ImGui frame with the mouse at `mouse` (viewport = whole display), calling `body`.
template <typename Body>
void imguiFrame(glm::dvec2 mouse, bool down, Body&& body) {
    ImGuiIO& io = ImGui::GetIO();
    io.MousePos = ImVec2(static_cast<float>(mouse.x), static_cast<float>(mouse.y));
    io.MouseDown[0] = down;
    ImGui::NewFrame();
    body(ImGui::GetForegroundDrawList());
    ImGui::Render();
}

class ImGuiGizmo : public ::testing::Test {
protected:
    void SetUp() override {
        ImGui::CreateContext();
        ImGuiIO& io = ImGui::GetIO();
        io.IniFilename = nullptr;
        io.DisplaySize = ImVec2(static_cast<float>(kWidth), static_cast<float>(kHeight));
        io.DeltaTime = 1.0f / 60.0f;
        unsigned char* pixels = nullptr;
        int w = 0, h = 0;
        io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
    }
    void TearDown() override { ImGui::DestroyContext(); }
};

TEST_F(ImGuiGizmo, HoverClickDragRelease) {
    const assets::ResolvedCamera camera = frontCamera();
    GizmoState state;
    LocalTransform local;
    GizmoResult result;
    const auto frame = [&](glm::dvec2 mouse, bool down) {
        imguiFrame(mouse, down, [&](ImDrawList* drawList) {
            result = gizmo(state, GizmoMode::Translate, camera, {0.0, 0.0}, kWidth, kHeight, glm::dmat4(1.0), local, drawList);
        });
        local = result.local;  // the caller previews the drag
    };
    frame(kCentre + glm::dvec2(80.0, 0.0), false);
    EXPECT_TRUE(result.hovered);
    EXPECT_FALSE(state.dragging);
    frame(kCentre + glm::dvec2(80.0, 0.0), true);
    EXPECT_TRUE(state.dragging);
    EXPECT_EQ(state.axis, 0);
    frame(kCentre + glm::dvec2(130.0, 20.0), true);
    EXPECT_TRUE(result.changed);
    EXPECT_GT(local.translation.x, 0.0);
    const double x = local.translation.x;
    frame(kCentre + glm::dvec2(130.0, 20.0), false);
    EXPECT_TRUE(result.released);
    EXPECT_FALSE(state.dragging);
    EXPECT_EQ(local.translation.x, x);
    EXPECT_EQ(state.originalLocal.translation, glm::dvec3(0.0));
    frame({20.0, 20.0}, false);
    EXPECT_FALSE(result.hovered || result.changed || result.released);
}

TEST_F(ImGuiGizmo, RotationKeepsTurningPastHalfATurn) {
    const assets::ResolvedCamera camera = frontCamera();
    GizmoState state;
    LocalTransform local;
    GizmoResult result;
    const auto at = [](double degrees) {
        const double a = glm::radians(degrees);
        return kCentre + 90.0 * glm::dvec2(std::cos(a), -std::sin(a));  // counter-clockwise on screen
    };
    for (double degrees = 0.0; degrees <= 270.0; degrees += 30.0) {
        imguiFrame(at(degrees), degrees > 0.0 || state.dragging, [&](ImDrawList* drawList) {
            result = gizmo(state, GizmoMode::Rotate, camera, {0.0, 0.0}, kWidth, kHeight, glm::dmat4(1.0), local, drawList);
        });
        local = result.local;
        if (degrees == 0.0) {
            ASSERT_TRUE(result.hovered);
            imguiFrame(at(0.0), true, [&](ImDrawList* drawList) {
                result = gizmo(state, GizmoMode::Rotate, camera, {0.0, 0.0}, kWidth, kHeight, glm::dmat4(1.0), local, drawList);
            });
            ASSERT_TRUE(state.dragging);
            ASSERT_EQ(state.axis, 2);
        }
    }
    // Three quarters of a turn about +z: x goes to -y.
    expectNear(local.rotation * glm::dvec3(1.0, 0.0, 0.0), {0.0, -1.0, 0.0}, 1e-9);
}

TEST_F(ImGuiGizmo, BoxesThroughTheCameraAreClippedAtTheNearPlane) {
    const assets::ResolvedCamera camera = frontCamera();
    Aabb box;
    box.extend(glm::dvec3(-50.0, -3.0, -50.0));
    box.extend(glm::dvec3(50.0, 3.0, 50.0));  // the camera is inside
    imguiFrame({-1.0, -1.0}, false, [&](ImDrawList* drawList) {
        drawBox(drawList, camera, {0.0, 0.0}, kWidth, kHeight, box, IM_COL32(255, 255, 0, 255));
        drawLightIcon(drawList, camera, {0.0, 0.0}, kWidth, kHeight, {1.0, 1.0, 0.0}, {0.0, -1.0, 0.0}, true, 0xffffffffu);
        drawLightIcon(drawList, camera, {0.0, 0.0}, kWidth, kHeight, {0.0, 0.0, 20.0}, {0.0, -1.0, 0.0}, false, 0xffffffffu);
        ASSERT_GT(drawList->VtxBuffer.Size, 0);
        for (const ImDrawVert& v : drawList->VtxBuffer) {
            EXPECT_TRUE(std::isfinite(v.pos.x) && std::isfinite(v.pos.y));
            EXPECT_TRUE(v.pos.x > -kWidth - 5 && v.pos.x < 2 * kWidth + 5 && v.pos.y > -kHeight - 5 && v.pos.y < 2 * kHeight + 5)
                << v.pos.x << ", " << v.pos.y;
        }
    });
}

}  // namespace
}  // namespace nimbus::sandbox::editor
