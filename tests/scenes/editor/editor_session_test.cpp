// Scripted editor sessions in a real window: edits land in the saved JSON exactly, refusals carry
// the loader's message and change nothing, the screenshot shows the UI around the viewport, time
// is deterministic, and the reference snapshot's error is `sandbox compare`'s.
#include <gtest/gtest.h>

#include <fstream>

#include <nlohmann/json.hpp>

#include "editor_test_support.h"
#include "nimbus/assets/gltf_file.h"

namespace nimbus::test {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

const fs::path kSmoke = kContentScenes / "smoke.gltf";
const std::string kMedia = "extensions.NIMBUS_participating_media.";

const Json* nodeNamed(const Json& root, const std::string& name) {
    for (const Json& node : root["nodes"])
        if (node.value("name", "") == name) return &node;
    return nullptr;
}

TEST(EditorSession, EditsMovesAddsUndoesRedoesAndSavesExactlyThat) {
    TempFolder dir;
    const fs::path out = dir / "edited.gltf";
    const ProcessResult r = runEditor(dir, kSmoke, {
        "select chimney",
        "set " + kMedia + "medium.extinction 7.25",
        "set " + kMedia + "medium.albedo [0.5, 0.6, 0.7]",
        "set translation [-2.0, 2.0, 0.3]",
        "add emitter puff",
        "set " + kMedia + "emitter.preset \"fire\"",
        "set translation [1.5, 0.0, -1.0]",
        "undo",                      // puff back at the origin
        "undo",                      // puff back to smoke
        "redo",                      // puff on fire again
        "add box crate",
        "delete",                    // the crate goes...
        "undo",                      // ...and comes back
        "frames 2",
        "save " + out.string(),
        "quit",
    });
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const Json saved = assets::readGltfFile(out).json, original = assets::readGltfFile(kSmoke).json;
    const Json* chimney = nodeNamed(saved, "chimney");
    ASSERT_NE(chimney, nullptr);
    EXPECT_EQ((*chimney)["extensions"]["NIMBUS_participating_media"]["medium"]["extinction"], 7.25);
    EXPECT_EQ((*chimney)["extensions"]["NIMBUS_participating_media"]["medium"]["albedo"], Json::array({0.5, 0.6, 0.7}));
    EXPECT_EQ((*chimney)["translation"], Json::array({-2.0, 2.0, 0.3}));
    const Json* puff = nodeNamed(saved, "puff");
    ASSERT_NE(puff, nullptr);
    EXPECT_EQ((*puff)["extensions"]["NIMBUS_participating_media"]["emitter"]["preset"], "fire");
    EXPECT_FALSE(puff->contains("translation"));
    EXPECT_NE(nodeNamed(saved, "crate"), nullptr);
    // Nothing else changed: every original node but the chimney is as it was.
    for (const Json& node : original["nodes"])
        if (node.value("name", "") != "chimney") {
            EXPECT_EQ(*nodeNamed(saved, node["name"]), node);
        }
    EXPECT_EQ(saved["extensions"]["NIMBUS_participating_media"], original["extensions"]["NIMBUS_participating_media"]);
}

TEST(EditorSession, InvalidSetFailsWithTheLoadersMessageAndChangesNothing) {
    const std::pair<std::string, std::string> refusals[] = {
        {kMedia + "medium.extinction -3", "medium.extinction"},
        {kMedia + "medium.g 1", "medium.g"},
        {kMedia + "emitter.preset \"drizzle\"", "emitter.preset"},
    };
    for (const auto& [set, field] : refusals) {
        SCOPED_TRACE(set);
        TempFolder dir;
        const ProcessResult r = runEditor(dir, kSmoke, {"select chimney", "set " + set, "save " + (dir / "never.gltf").string()});
        EXPECT_EQ(r.exitCode, 2);
        EXPECT_NE(r.err.find("script.txt:2: " + kSmoke.string() + ": node \"chimney\" (nodes[2]): " + kMedia + field),
                  std::string::npos) << r.err;
        EXPECT_FALSE(fs::exists(dir / "never.gltf"));
    }
}

// The viewport's pixels, display-encoded, appear in the screenshot: the UI is drawn around the live render.
TEST(EditorSession, ScreenshotShowsTheUiAroundANonEmptyViewport) {
    TempFolder dir;
    const ProcessResult r = runEditor(dir, kSmoke, {"time 2", "frames 2", "viewport " + (dir / "v.exr").string(),
                                                    "screenshot " + (dir / "ui.png").string(), "quit"}, "160x90");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const assets::RgbImage viewport = assets::readImage(dir / "v.exr"), shot = assets::readImage(dir / "ui.png");
    EXPECT_GT(shot.width, viewport.width + 400);  // outliner and inspector beside it
    double lo = 1e30, hi = -1e30;
    for (float v : viewport.rgb) lo = std::min(lo, static_cast<double>(v)), hi = std::max(hi, static_cast<double>(v));
    EXPECT_GT(hi - lo, 0.05) << "the viewport is flat";
    const std::vector<std::uint8_t> encoded = assets::displayEncode(viewport);
    // Overlays (media bounds, light icons) cover a few pixels: most must match.
    const auto matching = [&](int x0, int y0, int giveUp) {
        int matches = 0, misses = 0;
        for (int y = 0; y < viewport.height; y += 3)
            for (int x = 0; x < viewport.width; x += 3) {
                const std::size_t i = (static_cast<std::size_t>(y) * static_cast<std::size_t>(viewport.width) + static_cast<std::size_t>(x)) * 3;
                bool same = true;
                for (int c = 0; c < 3; ++c)
                    same = same && std::abs(shot.at(x0 + x, y0 + y)[c] - assets::srgbDecode(encoded[i + static_cast<std::size_t>(c)] / 255.0f)) < 1e-3f;
                (same ? matches : misses) += 1;
                if (misses > giveUp) return 0.0;
            }
        return static_cast<double>(matches) / (matches + misses);
    };
    double best = 0.0;
    const int samples = ((viewport.width + 2) / 3) * ((viewport.height + 2) / 3);
    for (int y = 0; y + viewport.height <= shot.height; ++y)
        for (int x = 0; x + viewport.width <= shot.width; ++x) best = std::max(best, matching(x, y, samples / 5));
    EXPECT_GT(best, 0.8) << "the viewport image is not in the screenshot";
    std::size_t uiPixels = 0;  // the menu bar's text and the panels' widgets
    for (int y = 0; y < shot.height; ++y)
        for (int x = 0; x < 200; ++x) uiPixels += shot.at(x, y).r > 0.3f ? 1 : 0;
    EXPECT_GT(uiPixels, 200u);
}

TEST(EditorSession, ScrubbingToTAndPlayingToTGiveTheSameImage) {
    TempFolder dir;
    const ProcessResult scrub = runEditor(dir, kSmoke, {"time 1.5", "viewport " + (dir / "scrubbed.exr").string(), "quit"}, "96x54");
    ASSERT_EQ(scrub.exitCode, 0) << scrub.err;
    const ProcessResult play = runEditor(dir, kSmoke, {"play 1.5", "viewport " + (dir / "played.exr").string(), "quit"}, "96x54");
    ASSERT_EQ(play.exitCode, 0) << play.err;
    const assets::RgbImage a = assets::readImage(dir / "scrubbed.exr"), b = assets::readImage(dir / "played.exr");
    EXPECT_EQ(a.rgb, b.rgb);
    EXPECT_EQ(a.rgb, renderWithSandbox(dir, kSmoke, "96x54", 1.5).rgb) << "and both equal sandbox render --time 1.5";
}

TEST(EditorSession, ReferenceSnapshotErrorIsSandboxCompares) {
    TempFolder dir;
    const ProcessResult r = runEditor(dir, kSmoke, {"time 2", "reference " + (dir / "ref.exr").string(),
                                                    "viewport " + (dir / "v.exr").string(), "quit"}, "80x45");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const double editor = numberAfter(r.out, "rel_rmse ");
    const ProcessResult compare = runProcess(sandboxExecutable(), {"compare", (dir / "v.exr").string(), (dir / "ref.exr").string(), "--json"});
    ASSERT_EQ(compare.exitCode, 0) << compare.err;
    const double sandbox = Json::parse(compare.out)["rel_rmse"].get<double>();
    EXPECT_GT(editor, 0.0);
    EXPECT_NEAR(editor, sandbox, 1e-8 * sandbox);
}

}  // namespace
}  // namespace nimbus::test
