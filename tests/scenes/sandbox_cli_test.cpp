// `sandbox render` run as a user runs it (docs/design.md §5): malformed scenes are refused with a
// non-zero exit and one line naming the file, third-party models render, a scene carrying our
// extension still draws its meshes, bad arguments are refused, and --stats reports the frame.
#include <gtest/gtest.h>

#include <cmath>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "nimbus/assets/image_io.h"
#include "nimbus/assets/scene.h"
#include "process.h"

namespace nimbus::test {
namespace {

namespace fs = std::filesystem;

const fs::path kData = NIMBUS_TEST_DATA_DIR;
const fs::path kContent = NIMBUS_CONTENT_DIR_FOR_TESTS;

ProcessResult sandbox(const std::vector<std::string>& args) { return runProcess(sandboxExecutable(), args); }


void expectRefused(const ProcessResult& r) {
    EXPECT_FALSE(r.signaled) << "crashed instead of refusing: " << explain(r);
    EXPECT_NE(r.exitCode, 0) << explain(r);
    EXPECT_FALSE(r.err.empty()) << "no reason given: " << explain(r);
}

int countPixels(const assets::RgbImage& image, const std::function<bool(const glm::vec3&)>& predicate) {
    int n = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) n += predicate(image.at(x, y)) ? 1 : 0;
    return n;
}

// ---- malformed input ----

std::vector<fs::path> boundsCheckingFiles() {
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(kData / "tinygltf/BoundsChecking"))
        if (entry.path().extension() == ".gltf" || entry.path().extension() == ".glb") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

TEST(SandboxRender, RefusesEveryBoundsCheckingFileWithOneLineNamingIt) {
    const std::vector<fs::path> files = boundsCheckingFiles();
    ASSERT_GE(files.size(), 4u);
    TempFolder out;
    for (const fs::path& file : files) {
        SCOPED_TRACE(file.filename().string());
        const fs::path image = out / (file.stem().string() + ".png");
        for (const char* command : {"render", "validate"}) {
            std::vector<std::string> args = {command, file.string()};
            if (std::string(command) == "render") args.insert(args.end(), {"--size", "32x24", "--out", image.string()});
            const ProcessResult r = sandbox(args);
            expectRefused(r);
            const std::vector<std::string> lines = r.errLines();
            ASSERT_EQ(lines.size(), 1u) << command << ": one line on stderr: " << explain(r);
            EXPECT_NE(lines[0].find(file.filename().string()), std::string::npos) << command << ": names the file: " << lines[0];
        }
        EXPECT_FALSE(fs::exists(image)) << "no image for a refused scene";
    }
}

TEST(SandboxRender, RefusesAMissingSceneFile) {
    const ProcessResult r = sandbox({"render", (kData / "no_such_scene.gltf").string(), "--size", "32x24"});
    expectRefused(r);
    ASSERT_EQ(r.errLines().size(), 1u) << explain(r);
    EXPECT_NE(r.err.find("no_such_scene.gltf"), std::string::npos) << r.err;
}

// ---- models that must render ----

struct Rendered {
    ProcessResult process;
    assets::RgbImage image;
};

Rendered renderToFile(const fs::path& scene, const fs::path& out, const std::string& size, std::vector<std::string> extra = {}) {
    std::vector<std::string> args = {"render", scene.string(), "--size", size, "--out", out.string()};
    args.insert(args.end(), extra.begin(), extra.end());
    Rendered r{sandbox(args), {}};
    EXPECT_FALSE(r.process.signaled) << explain(r.process);
    EXPECT_EQ(r.process.exitCode, 0) << explain(r.process);
    // (Drivers may log to stderr, so only our own messages are ruled out.)
    EXPECT_EQ(r.process.err.find("sandbox"), std::string::npos) << "a successful render reports no problem: " << r.process.err;
    EXPECT_TRUE(fs::exists(out)) << out;
    if (fs::exists(out)) r.image = assets::readImage(out);
    return r;
}

TEST(SandboxRender, KhronosBoxShowsTheRedBox) {
    // The acceptance command: sandbox render Box.gltf --size 320x240 --out box.png
    TempFolder out;
    const Rendered r = renderToFile(kData / "khronos/Box/Box.gltf", out / "box.png", "320x240");
    ASSERT_EQ(r.image.width, 320);
    ASSERT_EQ(r.image.height, 240);
    const int lit = countPixels(r.image, [](const glm::vec3& p) { return glm::length(p) > 0.0f; });
    const int red = countPixels(r.image, [](const glm::vec3& p) { return p.x > 0.05f && p.x > 4.0f * p.y && p.x > 4.0f * p.z; });
    EXPECT_GT(lit, 320 * 240 / 5) << "the box fills a good part of the frame";
    EXPECT_EQ(red, lit) << "every pixel that is not background is red";
    EXPECT_NE(r.process.out.find("320x240"), std::string::npos) << r.process.out;
}

TEST(SandboxRender, TinygltfCubeRendersItsTexture) {
    TempFolder out;
    const Rendered r = renderToFile(kData / "tinygltf/Cube/Cube.gltf", out / "cube.exr", "160x120");
    const int covered = countPixels(r.image, [](const glm::vec3& p) { return glm::length(p) > 0.0f; });
    EXPECT_GT(covered, 160 * 120 / 10);
    // A textured cube is not one flat colour: count distinct quantised colours among covered pixels.
    std::vector<int> keys;
    for (int y = 0; y < r.image.height; ++y)
        for (int x = 0; x < r.image.width; ++x) {
            const glm::vec3 p = r.image.at(x, y);
            if (glm::length(p) > 0.0f) keys.push_back(static_cast<int>(p.x * 64) * 4096 + static_cast<int>(p.y * 64) * 64 + static_cast<int>(p.z * 64));
        }
    std::sort(keys.begin(), keys.end());
    EXPECT_GT(std::unique(keys.begin(), keys.end()) - keys.begin(), 20);
}

TEST(SandboxRender, KhronosCamerasOrthographicCameraIsPickedByIndex) {
    // Cameras.gltf: two unnamed cameras at one place before a unit square tilted 45° about x;
    // cameras[1] is orthographic (xmag = ymag = 1): the square covers 1/2 of the width and
    // cos 45°/2 of the height, 17.7 % of the frame whatever the distance.
    TempFolder out;
    const fs::path file = kData / "khronos/Cameras/Cameras.gltf";
    const fs::path json = out / "stats.json";
    const Rendered ortho = renderToFile(file, out / "ortho.exr", "160x160", {"--camera", "1", "--stats", json.string()});
    const Rendered persp = renderToFile(file, out / "persp.exr", "160x160", {"--camera", "0"});
    std::ifstream in(json);
    EXPECT_EQ(nlohmann::json::parse(in).at("camera").get<std::string>(), "camera 1");
    auto covered = [](const Rendered& r) { return countPixels(r.image, [](const glm::vec3& p) { return glm::length(p) > 0.0f; }); };
    EXPECT_NEAR(covered(ortho), 0.5 * 0.5 * std::sqrt(0.5) * 160 * 160, 200.0);
    EXPECT_NE(covered(ortho), covered(persp));
    const ProcessResult unknown = sandbox({"render", file.string(), "--camera", "2", "--out", (out / "x.png").string()});
    EXPECT_NE(unknown.exitCode, 0);
    ASSERT_EQ(unknown.errLines().size(), 1u) << unknown.err;
    EXPECT_NE(unknown.err.find("0 (unnamed), 1 (unnamed)"), std::string::npos) << unknown.err;
}

TEST(SandboxRender, TinygltfBox01GlbRenders) {
    TempFolder out;
    const Rendered r = renderToFile(kData / "tinygltf/box01.glb", out / "box01.png", "160x120");
    EXPECT_GT(countPixels(r.image, [](const glm::vec3& p) { return glm::length(p) > 0.0f; }), 160 * 120 / 10);
}

TEST(SandboxRender, SceneWithTheMediaExtensionStillRendersItsMeshes) {
    TempFolder out;
    const fs::path scene = kContent / "scenes/cloud.gltf";
    const Rendered withMedium = renderToFile(scene, out / "cloud.exr", "160x90");
    ASSERT_EQ(withMedium.image.height, 90);
    // The meshes are drawn: the bottom rows see the ground, never the background radiance.
    const assets::Scene loaded = assets::loadScene(scene);
    const glm::vec3 background = loaded.environment.background;
    ASSERT_GT(glm::length(background), 0.1f) << "cloud.gltf has a sky colour; the check below relies on it";
    int ground = 0;
    for (int y = withMedium.image.height - 10; y < withMedium.image.height; ++y)
        for (int x = 0; x < withMedium.image.width; ++x) ground += glm::length(withMedium.image.at(x, y) - background) > 0.05f ? 1 : 0;
    EXPECT_EQ(ground, 10 * withMedium.image.width);

    // The medium is drawn too: the same file without the node extensions renders differently.
    std::ifstream in(scene);
    nlohmann::json gltf = nlohmann::json::parse(in);
    int stripped = 0;
    for (auto& node : gltf.at("nodes"))
        if (node.contains("extensions") && node.at("extensions").contains("NIMBUS_participating_media")) {
            node.at("extensions").erase("NIMBUS_participating_media");
            ++stripped;
        }
    ASSERT_GT(stripped, 0) << "cloud.gltf carries a medium";
    for (const auto& buffer : gltf.at("buffers"))
        fs::copy_file(scene.parent_path() / buffer.at("uri").get<std::string>(), out / buffer.at("uri").get<std::string>());
    std::ofstream(out / "no_medium.gltf") << gltf.dump();
    const Rendered withoutMedium = renderToFile(out / "no_medium.gltf", out / "no_medium.exr", "160x90");
    ASSERT_EQ(withoutMedium.image.width, withMedium.image.width);
    int changed = 0;
    for (int y = 0; y < withMedium.image.height; ++y)
        for (int x = 0; x < withMedium.image.width; ++x)
            changed += glm::length(withMedium.image.at(x, y) - withoutMedium.image.at(x, y)) > 0.02f ? 1 : 0;
    EXPECT_GT(changed, 160 * 90 / 20) << "the cloud covers part of the frame";
}

// ---- bad arguments ----

TEST(SandboxRender, RefusesBadArgumentsWithAReason) {
    const std::string box = (kData / "khronos/Box/Box.gltf").string();
    struct Case {
        std::vector<std::string> args;
        std::string mentions;  // what the reason must name
        bool parseError;       // found by the command-line parser: the line also points to --help
    };
    const Case cases[] = {
        {{"render"}, "scene", true},
        {{"render", box, "--size", "0x10"}, "--size", false},
        {{"render", box, "--size", "abc"}, "--size", false},
        {{"render", box, "--size", "64x"}, "--size", false},
        {{"render", box, "--bogus"}, "--bogus", true},
        {{"render", box, "--set", "no_such_setting=1"}, "no_such_setting", false},
        {{"render", box, "--set", "shadow_map_size"}, "shadow_map_size", false},
        {{"render", box, "--stats", "/dev/null", "--frames", "5"}, "--frames", false},
        {{"render", box, "--quality", "turbo"}, "--quality", false},
        {{"render", box, "--mode", "voxels"}, "--mode", false},
        {{"render", box, "--budget-ms", "0"}, "--budget-ms", false},
        {{"render", box, "--budget-ms", "NaN"}, "--budget-ms", false},
        {{"render", box, "--budget-ms", "-5"}, "--budget-ms", false},
        {{"render", box, "--budget-ms", "abc"}, "--budget-ms", false},
        {{"render", box, "--animate"}, "--stats", true},
        {{}, "subcommand", true},
    };
    for (const Case& c : cases) {
        std::string joined;
        for (const auto& a : c.args) joined += " " + a;
        SCOPED_TRACE("sandbox" + joined);
        const ProcessResult r = sandbox(c.args);
        expectRefused(r);
        EXPECT_EQ(r.exitCode, 2) << explain(r);
        EXPECT_NE(r.err.find(c.mentions), std::string::npos) << explain(r);
        ASSERT_EQ(r.errLines().size(), 1u) << explain(r);
        EXPECT_EQ(r.err.rfind("sandbox: ", 0), 0u) << explain(r);
        if (c.parseError) {
            EXPECT_NE(r.err.find("--help"), std::string::npos) << "points to the usage: " << explain(r);
        }
        EXPECT_TRUE(r.out.empty()) << "nothing on stdout: " << r.out;
    }
}

// A scene's render block is checked like the command line, and the message names the node and field.
TEST(SandboxRender, RefusesAnUnknownQualityInASceneNamingTheField) {
    TempFolder out;
    std::ifstream in(kContent / "scenes/smoke.gltf");
    nlohmann::json gltf = nlohmann::json::parse(in);
    for (auto& node : gltf["nodes"])
        if (node.contains("extensions") && node["extensions"].contains("NIMBUS_participating_media"))
            node["extensions"]["NIMBUS_participating_media"]["render"] = {{"quality", "turbo"}};
    // Buffers are referenced relative to the scene: the .bin goes beside the copy.
    const fs::path scene = out / "turbo.gltf";
    std::ofstream(scene) << gltf.dump();
    fs::copy_file(kContent / "scenes/smoke.bin", out / "smoke.bin");
    const ProcessResult r = sandbox({"render", scene.string(), "--size", "32x18", "--out", (out / "x.png").string()});
    expectRefused(r);
    EXPECT_EQ(r.errLines().size(), 1u) << explain(r);
    for (const char* part : {"render.quality", "turbo", "exact, balanced or fast"})
        EXPECT_NE(r.err.find(part), std::string::npos) << part << ": " << explain(r);
}

// --budget-ms walks the quality ladder and reports the rung it keeps: a generous budget keeps the
// lowest-error rung, an impossible one the fastest.
TEST(SandboxRender, BudgetReportsTheChosenRung) {
    TempFolder out;
    for (const auto& [budget, expected] : {std::pair<const char*, const char*>{"100000", "exact"},
                                           std::pair<const char*, const char*>{"0.001", "fast media_scale=0.25"}}) {
        const fs::path json = out / "stats.json";
        const ProcessResult r = sandbox({"render", (kContent / "scenes/smoke.gltf").string(), "--time", "2", "--size", "48x27",
                                         "--budget-ms", budget, "--stats", json.string(), "--out", (out / "b.png").string()});
        ASSERT_EQ(r.exitCode, 0) << explain(r);
        EXPECT_NE(r.out.find(std::string("chose ") + expected), std::string::npos) << r.out;
        std::ifstream in(json);
        const nlohmann::json stats = nlohmann::json::parse(in);
        EXPECT_EQ(stats.at("chosen").get<std::string>(), expected);
        EXPECT_DOUBLE_EQ(stats.at("budget_ms").get<double>(), std::stod(budget));
    }
}

TEST(SandboxRender, QualityIsReportedInTheStats) {
    TempFolder out;
    for (const char* quality : {"fast", "balanced", "exact"}) {
        const fs::path json = out / "stats.json";
        const ProcessResult r = sandbox({"render", (kContent / "scenes/smoke.gltf").string(), "--time", "2", "--size", "48x27",
                                         "--quality", quality, "--stats", json.string(), "--out", (out / "q.png").string()});
        ASSERT_EQ(r.exitCode, 0) << explain(r);
        std::ifstream in(json);
        const nlohmann::json stats = nlohmann::json::parse(in);
        EXPECT_EQ(stats.at("quality").get<std::string>(), quality);
        EXPECT_EQ(stats.at("media_exact_lighting").get<bool>(), std::string(quality) == "exact") << quality;
    }
}

// --animate steps the simulation before each timed frame, so a moving medium's costs are in the
// frame: the multiple model's grid is solved again every frame (its CPU time reported), where a
// still frame keeps the first frame's answer.
TEST(SandboxRender, AnimateStepsTheSimulationAndSolvesTheGridEachFrame) {
    TempFolder out;
    for (const bool animate : {false, true}) {
        const fs::path json = out / "stats.json";
        std::vector<std::string> args{"render", (kContent / "scenes/smoke.gltf").string(), "--time", "2", "--size", "48x27",
                                      "--quality", "fast", "--stats", json.string(), "--out", (out / "a.png").string()};
        if (animate) args.push_back("--animate");
        const ProcessResult r = sandbox(args);
        ASSERT_EQ(r.exitCode, 0) << explain(r);
        std::ifstream in(json);
        const nlohmann::json stats = nlohmann::json::parse(in);
        EXPECT_EQ(stats.at("animate").get<bool>(), animate);
        EXPECT_TRUE(stats.at("media_multiple_scattering").get<bool>());
        const int frames = stats.at("frames").get<int>();
        // Three warm-up frames and two timed loops, a 1/60 s step before each.
        EXPECT_NEAR(stats.at("time").get<double>(), 2.0 + (animate ? (3 + 2 * frames) / 60.0 : 0.0), 1e-6);
        if (animate)
            EXPECT_GT(stats.at("media_scattering_solve_ms").get<double>(), 0.0);
        else
            EXPECT_EQ(stats.at("media_scattering_solve_ms").get<double>(), 0.0);
        EXPECT_EQ(stats.at("media_scattering_warm_frames").get<int>(), 0) << "a cold solve unless a host asks";
    }
}

// scattering_warm_sweeps: every timed frame of a moving plume starts its grid's solve from the
// frame before's.
TEST(SandboxRender, AWarmStartSolvesAMovingPlumeFromTheFrameBefore) {
    TempFolder out;
    const fs::path json = out / "stats.json";
    const ProcessResult r = sandbox({"render", (kContent / "scenes/smoke.gltf").string(), "--time", "2", "--size", "48x27", "--quality", "fast",
                                     "--animate", "--set", "scattering_warm_sweeps=16", "--stats", json.string(), "--out",
                                     (out / "a.png").string()});
    ASSERT_EQ(r.exitCode, 0) << explain(r);
    std::ifstream in(json);
    const nlohmann::json stats = nlohmann::json::parse(in);
    EXPECT_EQ(stats.at("media_scattering_warm_frames").get<int>(), stats.at("frames").get<int>());
    EXPECT_GT(stats.at("media_scattering_solve_ms").get<double>(), 0.0);
}

// A lamp inside the medium: balanced keeps its splats (their near field takes the exact tier's
// quadrature and neighbour order) unless exact_near_lamps asks for per-fragment shading.
TEST(SandboxRender, BalancedKeepsItsSplatsAroundALampInsideTheMedium) {
    TempFolder out;
    for (const bool exactNearLamps : {false, true}) {
        const fs::path json = out / "stats.json";
        std::vector<std::string> args{"render", (kContent / "scenes/campfire.gltf").string(), "--time", "4", "--size", "48x27",
                                      "--quality", "balanced", "--stats", json.string(), "--out", (out / "lamp.png").string()};
        if (exactNearLamps) args.insert(args.end(), {"--set", "exact_near_lamps=on"});
        const ProcessResult r = sandbox(args);
        ASSERT_EQ(r.exitCode, 0) << explain(r);
        std::ifstream in(json);
        const nlohmann::json stats = nlohmann::json::parse(in);
        EXPECT_EQ(stats.at("media_exact_lighting").get<bool>(), exactNearLamps);
        if (!exactNearLamps) {
            EXPECT_GT(stats.at("media_lamp_particles").get<long long>(), 0);
        }
    }
}

// At full resolution the splats of particles no mesh box comes near are clipped by the depth test
// alone; a reduced layer has no depth of its size, so every splat fetches it.
TEST(SandboxRender, FullResolutionSplatsClearOfMeshesTakeTheDepthTest) {
    TempFolder out;
    for (const char* scale : {"1", "0.5"}) {
        const fs::path json = out / "stats.json";
        const ProcessResult r = sandbox({"render", (kContent / "scenes/smoke.gltf").string(), "--time", "8", "--size", "96x54", "--quality",
                                         "fast", "--set", std::string("media_scale=") + scale, "--stats", json.string(), "--out",
                                         (out / "d.png").string()});
        ASSERT_EQ(r.exitCode, 0) << explain(r);
        std::ifstream in(json);
        const nlohmann::json stats = nlohmann::json::parse(in);
        const long long tested = stats.at("media_depth_tested_particles").get<long long>();
        if (std::string(scale) == "1") {
            EXPECT_GT(tested, 0);
            EXPECT_LT(tested, stats.at("media_particles").get<long long>()) << "the particles on the ground fetch the depth";
        } else {
            EXPECT_EQ(tested, 0);
        }
    }
}

TEST(SandboxSettings, ListsEverySettingWithWhereItActs) {
    const ProcessResult r = sandbox({"settings"});
    ASSERT_EQ(r.exitCode, 0) << explain(r);
    for (const char* key : {"quality", "mode", "lighting", "slice_deposit", "media_scale", "shadow_map_size", "in mode blocks",
                            "tier exact", "(fast: 16; blocks in fast where a mesh reaches into the medium: 32)",
                            "particles, blocks, raymarch, sheets or billboards"})
        EXPECT_NE(r.out.find(key), std::string::npos) << key << " missing from:\n" << r.out;
}

// docs/scene-format.schema.json's render block is what `sandbox settings --schema` prints from the
// declarations, so the schema, the help and the parser cannot disagree.
TEST(SandboxSettings, TheDocumentedSchemaIsTheGeneratedOne) {
    const ProcessResult r = sandbox({"settings", "--schema"});
    ASSERT_EQ(r.exitCode, 0) << explain(r);
    std::ifstream in(NIMBUS_DOCS_DIR "/scene-format.schema.json");
    ASSERT_TRUE(in);
    const nlohmann::json documented = nlohmann::json::parse(in)["$defs"]["render"];
    EXPECT_EQ(documented, nlohmann::json::parse(r.out)) << "regenerate with tools/update_render_schema.py";
}

TEST(SandboxRender, HelpPrintsTheUsage) {
    const ProcessResult r = sandbox({"render", "--help"});
    EXPECT_FALSE(r.signaled);
    EXPECT_EQ(r.exitCode, 0) << explain(r);
    for (const char* option : {"--out", "--size", "--stats", "--set", "--time"})
        EXPECT_NE(r.out.find(option), std::string::npos) << option << " missing from:\n" << r.out;
}

// ---- --stats ----

TEST(SandboxRender, StatsReportTheFrame) {
    TempFolder out;
    const fs::path json = out / "stats.json";
    const Rendered r = renderToFile(kContent / "scenes/demo.gltf", out / "demo.png", "96x64", {"--stats", json.string()});
    ASSERT_TRUE(fs::exists(json));
    std::ifstream in(json);
    const nlohmann::json stats = nlohmann::json::parse(in);
    EXPECT_EQ(stats.at("width").get<int>(), 96);
    EXPECT_EQ(stats.at("height").get<int>(), 64);
    EXPECT_GT(stats.at("frame_ms").get<double>(), 0.0);
    EXPECT_GE(stats.at("frames").get<int>(), 20);
    EXPECT_FALSE(stats.at("gl_renderer").get<std::string>().empty());
    EXPECT_EQ(stats.at("gl_errors").get<int>(), 0);
    EXPECT_EQ(stats.at("camera").get<std::string>(), "main");
    const nlohmann::json& passes = stats.at("passes_ms");
    ASSERT_TRUE(passes.is_object()) << stats.dump();
    for (const char* pass : {"shadow_maps", "opaque", "compose"}) {
        ASSERT_TRUE(passes.contains(pass)) << pass << " in " << passes.dump();
        EXPECT_GT(passes.at(pass).get<double>(), 0.0) << pass;
    }
}

}  // namespace
}  // namespace nimbus::test
