// The editor driven as a person drives it: X input from xdotool on the private Xvfb display, no
// script. A click on the cloud in the viewport selects it, a drag of the gizmo's x axis moves it, a
// value typed into the inspector's extinction field sets it, and Ctrl+S saves. The saved file must
// hold exactly those edits: the move the gizmo makes of that drag, and the typed value.
//
// The window's title ("cloud.gltf* - Nimbus editor") says when the scene is shown, when an edit
// is in and when it is saved; the test waits on it rather than on the clock.
#include <gtest/gtest.h>

#include <cmath>
#include <thread>

#include <nlohmann/json.hpp>

#include "editor_test_support.h"
#include "nimbus/assets/gltf_file.h"
#include "nimbus/assets/scene.h"
#include "nimbus/assets/scene_queries.h"
#include "viewport/gizmo.h"
#include "viewport/picking.h"

namespace nimbus::test {
namespace {

namespace fs = std::filesystem;
namespace ed = sandbox::editor;
using Json = nlohmann::json;

constexpr int kWidth = 320, kHeight = 180;
// Where the editor lays its windows out at this viewport size, in window pixels (editor_app.cpp's
// layout with Dear ImGui's default style and font): the viewport image's top-left corner (outliner
// 270 + padding 2; menu 19 + title 19 + padding 2 + toolbar 19 + spacing 4), and the middle of the
// inspector's extinction field for a node with a transform and a medium (its sixth row).
const glm::dvec2 kViewportOrigin(272.0, 63.0);
const glm::ivec2 kExtinctionField(1008, 193);

std::string px(double v) { return std::to_string(static_cast<long>(std::lround(v))); }

// Waits until the editor's window carries this title; returns its X window id.
std::string waitForTitle(const std::string& pattern, RunningEditor& editor) {
    const ProcessResult r = xdotool({"search", "--sync", "--name", pattern});
    EXPECT_EQ(r.exitCode, 0) << "no window titled " << pattern << " (" << r.describe() << "); the editor "
                             << (editor.running() ? "is still running" : "exited") << ":\n" << editor.err();
    return r.out.substr(0, r.out.find('\n'));
}

void input(const std::vector<std::string>& args) {
    const ProcessResult r = xdotool(args, 60);
    EXPECT_EQ(r.exitCode, 0) << r.describe() << "\n" << r.err;
}

TEST(EditorInput, ClickDragTypeAndSaveLandExactlyInTheFile) {
    TempFolder dir;
    const fs::path scene = dir / "cloud.gltf";
    fs::copy_file(kContentScenes / "cloud.gltf", scene);
    fs::copy_file(kContentScenes / "cloud.bin", dir / "cloud.bin");
    const Json original = assets::readGltfFile(scene).json;

    // What the viewport shows: the scene's camera at the viewport's aspect, the cloud at (0, 4, 0)
    // and its node's gizmo at the node's origin.
    const assets::Scene loaded = assets::loadScene(scene);
    const assets::ResolvedCamera camera = assets::resolveCamera(loaded, assets::computeWorldTransforms(loaded, 0.0), "", Aabb{},
                                                                static_cast<double>(kWidth) / kHeight);
    const auto cloud = ed::projectToViewport(camera, glm::dvec3(0.0, 4.0, 0.0), kWidth, kHeight);
    const auto centre = ed::projectToViewport(camera, glm::dvec3(0.0), kWidth, kHeight);
    const double length = ed::kGizmoSizePixels * ed::worldPerPixel(camera, ed::viewDepth(camera, glm::dvec3(0.0)), kHeight);
    const auto tip = ed::projectToViewport(camera, glm::dvec3(length, 0.0, 0.0), kWidth, kHeight);
    ASSERT_TRUE(cloud && centre && tip);
    // Mouse positions are whole pixels: grab the x handle 60% along it and drag 40 pixels right.
    const glm::dvec2 grab = glm::round(*centre + 0.6 * (*tip - *centre)), release = grab + glm::dvec2(40.0, 0.0);
    ASSERT_EQ(ed::hitGizmo(ed::GizmoMode::Translate, camera, kWidth, kHeight, glm::dmat4(1.0), grab), 0);
    const ed::LocalTransform moved =
        ed::dragGizmo(ed::GizmoMode::Translate, 0, camera, kWidth, kHeight, glm::dmat4(1.0), ed::LocalTransform{}, grab, release);
    ASSERT_GT(moved.translation.x, 0.0);

    RunningEditor editor(dir, scene, std::to_string(kWidth) + "x" + std::to_string(kHeight));
    const std::string window = waitForTitle("^cloud\\.gltf - Nimbus editor$", editor);
    ASSERT_FALSE(HasFailure());
    const auto at = [&](glm::dvec2 viewport) {
        const glm::dvec2 p = kViewportOrigin + glm::round(viewport);
        return std::vector<std::string>{"mousemove", "--window", window, px(p.x), px(p.y)};
    };
    const auto then = [](std::vector<std::string> a, const std::vector<std::string>& b) {
        a.insert(a.end(), b.begin(), b.end());
        return a;
    };
    input({"windowfocus", window});
    // Select: a left click on the cloud.
    input(then(at(*cloud), {"sleep", "0.5", "click", "1", "sleep", "0.5"}));
    // Move: press on the x handle, drag in steps, let go where it ends.
    std::vector<std::string> drag = then(at(grab), {"sleep", "0.5", "mousedown", "1", "sleep", "0.3"});
    for (int step = 1; step <= 4; ++step) drag = then(drag, then(at(grab + 0.25 * step * (release - grab)), {"sleep", "0.3"}));
    input(then(drag, {"sleep", "0.5", "mouseup", "1"}));
    waitForTitle("^cloud\\.gltf\\* - Nimbus editor$", editor);
    ASSERT_FALSE(HasFailure()) << "the drag made no edit";
    // Type: Ctrl+click turns the extinction field into a text field, all selected; type, then Return.
    input({"mousemove", "--window", window, std::to_string(kExtinctionField.x), std::to_string(kExtinctionField.y), "sleep", "0.5",
           "keydown", "ctrl", "sleep", "0.3", "click", "1", "sleep", "0.3", "keyup", "ctrl", "sleep", "0.5"});
    input({"type", "--delay", "100", "7.25"});
    // Keys are held a while, as fingers hold them: Dear ImGui 1.86 reads a key's state once per
    // frame, so a tap shorter than a frame would be lost.
    input({"keydown", "Return", "sleep", "0.3", "keyup", "Return", "sleep", "1"});
    // Save with the shortcut.
    input({"keydown", "ctrl", "sleep", "0.2", "keydown", "s", "sleep", "0.3", "keyup", "s", "sleep", "0.2", "keyup", "ctrl"});
    waitForTitle("^cloud\\.gltf - Nimbus editor$", editor);
    ASSERT_FALSE(HasFailure()) << "Ctrl+S did not save";

    Json expected = original;
    Json& node = expected["nodes"][1];
    ASSERT_EQ(node["name"], "cloud");
    node["translation"] = {moved.translation.x, moved.translation.y, moved.translation.z};
    node["rotation"] = {0.0, 0.0, 0.0, 1.0};
    node["scale"] = {1.0, 1.0, 1.0};
    node["extensions"]["NIMBUS_participating_media"]["medium"]["extinction"] = 7.25;
    const Json saved = assets::readGltfFile(scene).json;
    EXPECT_EQ(saved["nodes"][1], node);
    EXPECT_EQ(saved, expected) << "the save changed more than the move and the typed value";
}

}  // namespace
}  // namespace nimbus::test
