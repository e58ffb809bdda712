// The editor's files: every content scene opens, renders like `sandbox render`, and saves to a
// file that is valid (sandbox validate, the Khronos validator) and renders bit for bit alike.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

#include <nlohmann/json.hpp>

#include "editor_test_support.h"
#include "nimbus/assets/gltf_file.h"

namespace nimbus::test {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> contentScenes() {
    std::vector<fs::path> scenes;
    for (const auto& entry : fs::directory_iterator(kContentScenes))
        if (entry.path().extension() == ".gltf" || entry.path().extension() == ".glb") scenes.push_back(entry.path());
    std::sort(scenes.begin(), scenes.end());
    return scenes;
}

void expectSameImage(const assets::RgbImage& a, const assets::RgbImage& b, const std::string& what) {
    ASSERT_EQ(a.width, b.width) << what;
    ASSERT_EQ(a.height, b.height) << what;
    std::size_t differing = 0;
    for (std::size_t i = 0; i < a.rgb.size(); ++i) differing += a.rgb[i] != b.rgb[i] ? 1 : 0;
    EXPECT_EQ(differing, 0u) << what << ": channel values that differ";
}

TEST(EditorFiles, EveryContentSceneOpensRendersAndSavesUnchanged) {
    TempFolder dir;
    std::vector<std::string> saved;
    for (const fs::path& scene : contentScenes()) {
        SCOPED_TRACE(scene.filename().string());
        const std::string name = scene.stem().string();
        const fs::path out = dir / ("saved/" + name + ".gltf"), viewport = dir / (name + "_viewport.exr");
        const ProcessResult r = runEditor(dir, scene, {"frames 1", "viewport " + viewport.string(), "save " + out.string(), "quit"});
        ASSERT_EQ(r.exitCode, 0) << r.describe() << "\n" << r.err;
        const assets::RgbImage original = renderWithSandbox(dir, scene, "128x72");
        expectSameImage(assets::readImage(viewport), original, "the viewport against sandbox render");
        expectSameImage(renderWithSandbox(dir, out, "128x72"), original, "the saved file against the original");
        EXPECT_EQ(assets::readGltfFile(out).json, assets::readGltfFile(scene).json) << "the saved JSON";
        const ProcessResult valid = runProcess(sandboxExecutable(), {"validate", out.string()});
        EXPECT_EQ(valid.exitCode, 0) << valid.err;
        saved.push_back(out.string());
    }
    std::vector<std::string> args = {NIMBUS_GLTF_VALIDATOR};
    args.insert(args.end(), saved.begin(), saved.end());
    const ProcessResult khronos = runProcess(NIMBUS_NODE_EXE, args);
    EXPECT_EQ(khronos.exitCode, 0) << khronos.out << khronos.err;
}

TEST(EditorFiles, SavingAsGlbRendersAlike) {
    TempFolder dir;
    const fs::path scene = kContentScenes / "campfire.gltf", out = dir / "campfire.glb";
    const ProcessResult r = runEditor(dir, scene, {"save " + out.string(), "quit"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    expectSameImage(renderWithSandbox(dir, out, "96x54"), renderWithSandbox(dir, scene, "96x54"), "the .glb against the .gltf");
    const ProcessResult khronos = runProcess(NIMBUS_NODE_EXE, {NIMBUS_GLTF_VALIDATOR, out.string()});
    EXPECT_EQ(khronos.exitCode, 0) << khronos.out << khronos.err;
}

// A script never runs on the empty scene the interactive editor falls back to: a scene that cannot
// be opened ends a scripted run before its first command, with one line naming the file.
TEST(EditorFiles, AMalformedFileEndsAScriptBeforeItRuns) {
    TempFolder dir;
    const fs::path bad = fs::path(NIMBUS_TEST_DATA_DIR) / "malformed/accessor_out_of_range.gltf";
    const ProcessResult r = runEditor(dir, bad, {"screenshot " + (dir / "ui.png").string(), "quit"});
    EXPECT_EQ(r.exitCode, 2) << r.err;
    ASSERT_EQ(r.errLines().size(), 1u) << r.err;
    EXPECT_EQ(r.err.rfind("sandbox: " + bad.string() + ": ", 0), 0u) << r.err;
    EXPECT_FALSE(fs::exists(dir / "ui.png")) << "the script did not run";
    // Opening a malformed file from a script is a failing command: the scene it had stays open.
    const ProcessResult again = runEditor(dir, kContentScenes / "smoke.gltf", {"open " + bad.string(), "quit"});
    EXPECT_EQ(again.exitCode, 2);
    EXPECT_NE(again.err.find("script.txt:1: " + bad.string()), std::string::npos) << again.err;
}

TEST(EditorFiles, ExternalUrisOutsideTheSceneFolderAreRefused) {
    TempFolder dir;
    fs::create_directories(dir / "scene");
    nlohmann::json json = assets::readGltfFile(kContentScenes / "smoke.gltf").json;
    fs::copy_file(kContentScenes / "smoke.bin", dir / "smoke.bin");
    json["buffers"][0]["uri"] = "../smoke.bin";
    std::ofstream(dir / "scene/escape.gltf") << json.dump();
    const ProcessResult r = runEditor(dir, dir / "scene/escape.gltf", {"quit"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(r.errLines().size(), 1u) << r.err;
    EXPECT_NE(r.err.find("escape.gltf"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("buffers[0]"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace nimbus::test
