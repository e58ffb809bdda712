// mini_host, the second host, against Nimbus's renderer: every content scene rendered by both at
// the same size and time, in each media mode and at a reduced media resolution. The plugin's passes
// run on the same inputs in both, so the media match exactly; the images differ only where
// mini_host's own mesh shading rounds differently (the point light of campfire.gltf, up to 3e-7).
// mini_host shades glTF materials by their factors alone, so both render a copy of each scene
// without its textures (withoutTextures).
// Also: a bad command line exits 2 with one line, a broken extension exits 1 naming the field.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "../../scenes/process.h"
#include "nimbus/assets/image_io.h"
#include "nimbus/media/reference/image_metrics.h"

namespace nimbus::test {
namespace {

// Rel-RMSE and 99th-percentile bounds of mini_host's image against `sandbox render`.
constexpr double kImageRelRmse = 1e-6;
constexpr double kImageP99 = 1e-6;
// With a standard-depth host (AStandardDepthHostGetsTheSameImage).
constexpr double kStandardDepthRelRmse = 1e-4;

std::filesystem::path miniHost() { return sandboxExecutable().parent_path() / "mini_host"; }
std::string content(const std::string& scene) { return std::string(NIMBUS_CONTENT_DIR_FOR_TESTS) + "/scenes/" + scene + ".gltf"; }

// A copy of a content scene in `folder` whose materials read no texture (its .bin copied beside it).
std::string withoutTextures(const std::string& scene, const TempFolder& folder) {
    const std::filesystem::path source = content(scene);
    std::ifstream in(source);
    nlohmann::json gltf = nlohmann::json::parse(in);
    for (auto& m : gltf["materials"]) {
        if (m.contains("pbrMetallicRoughness")) {
            m["pbrMetallicRoughness"].erase("baseColorTexture");
            m["pbrMetallicRoughness"].erase("metallicRoughnessTexture");
        }
        m.erase("emissiveTexture");
    }
    gltf.erase("textures");
    gltf.erase("images");
    gltf.erase("samplers");
    for (const auto& buffer : gltf["buffers"]) {
        const std::string uri = buffer["uri"].get<std::string>();
        std::filesystem::copy_file(source.parent_path() / uri, folder / uri, std::filesystem::copy_options::overwrite_existing);
    }
    const std::filesystem::path out = folder / (scene + ".gltf");
    std::ofstream(out) << gltf.dump();
    return out.string();
}

struct Case {
    const char* scene;
    const char* time;
};
void PrintTo(const Case& c, std::ostream* os) { *os << c.scene << " at t=" << c.time << " s"; }
// Times on the 1/60 s step both hosts simulate emitters on.
const Case kScenes[] = {{"cloud", "0"},     {"smoke", "8"},         {"campfire", "4"}, {"jet", "6"},
                        {"explosion", "0.8"}, {"cumulus", "0"}, {"cumulus_aircraft", "0"}, {"demo", "0"}};

struct Mode {
    const char* name;
    std::vector<std::string> mini, sandbox;
};
const Mode kModes[] = {{"particles", {}, {}},
                       {"blocks", {"--mode", "blocks"}, {"--mode", "blocks"}},
                       {"billboards", {"--mode", "billboards"}, {"--mode", "billboards"}},
                       {"sheets", {"--mode", "sheets"}, {"--mode", "sheets"}},
                       {"half", {"--media-scale", "0.5"}, {"--set", "media_scale=0.5"}}};

class MiniHostMatchesSandbox : public ::testing::TestWithParam<Case> {};

TEST_P(MiniHostMatchesSandbox, InEveryMode) {
    const Case c = GetParam();
    TempFolder folder;
    const std::string scene = withoutTextures(c.scene, folder);
    for (const Mode& mode : kModes) {
        const std::string mini = (folder / (std::string(mode.name) + "_mini.exr")).string();
        const std::string nimbus = (folder / (std::string(mode.name) + "_nimbus.exr")).string();
        std::vector<std::string> a{scene, "--size", "256x144", "--time", c.time, "--out", mini};
        a.insert(a.end(), mode.mini.begin(), mode.mini.end());
        std::vector<std::string> b{"render", scene, "--size", "256x144", "--time", c.time, "--quality", "exact", "--out", nimbus};
        b.insert(b.end(), mode.sandbox.begin(), mode.sandbox.end());
        const ProcessResult ra = runProcess(miniHost(), a), rb = runProcess(sandboxExecutable(), b);
        ASSERT_EQ(ra.exitCode, 0) << mode.name << ": " << ra.describe() << "\n" << ra.err;
        ASSERT_EQ(rb.exitCode, 0) << mode.name << ": " << rb.describe() << "\n" << rb.err;
        const media::reference::ImageMetrics m = media::reference::compareImages(assets::readImage(mini), assets::readImage(nimbus));
        EXPECT_EQ(m.nonfinite, 0u) << mode.name;
        EXPECT_LE(m.relRmse, kImageRelRmse) << c.scene << " " << mode.name;
        EXPECT_LE(m.p99Abs, kImageP99) << c.scene << " " << mode.name;
    }
}

INSTANTIATE_TEST_SUITE_P(ContentScenes, MiniHostMatchesSandbox, ::testing::ValuesIn(kScenes),
                         [](const ::testing::TestParamInfo<Case>& p) { return std::string(p.param.scene); });

// A host whose depth buffer is standard (0 at the near plane) hands it over as such; the plugin
// re-encodes it (media_host_depth). The opaque scene is the same image; the media differ only by
// the precision the two encodings keep of the scene depth where particles meet meshes.
TEST(MiniHost, AStandardDepthHostGetsTheSameImage) {
    TempFolder folder;
    for (const Case c : {Case{"smoke", "8"}, Case{"cumulus_aircraft", "0"}, Case{"campfire", "4"}}) {
        for (const char* scale : {"1", "0.5"}) {
            const std::string mini = (folder / "standard.exr").string(), nimbus = (folder / "nimbus.exr").string();
            const ProcessResult ra = runProcess(miniHost(), {content(c.scene), "--size", "256x144", "--time", c.time, "--depth", "standard",
                                                             "--media-scale", scale, "--out", mini});
            const ProcessResult rb = runProcess(sandboxExecutable(), {"render", content(c.scene), "--size", "256x144", "--time", c.time,
                                                                      "--quality", "exact", "--set", std::string("media_scale=") + scale,
                                                                      "--out", nimbus});
            ASSERT_EQ(ra.exitCode, 0) << ra.describe() << "\n" << ra.err;
            ASSERT_EQ(rb.exitCode, 0) << rb.describe() << "\n" << rb.err;
            const media::reference::ImageMetrics m = media::reference::compareImages(assets::readImage(mini), assets::readImage(nimbus));
            EXPECT_LE(m.relRmse, kStandardDepthRelRmse) << c.scene << " media_scale " << scale;
        }
    }
}

// Mixed resolution through the host contract: fast at half resolution redraws the aircraft's edges
// in cumulus_aircraft at full resolution (MediaLayer::edges), and mini_host composes them as
// Nimbus does. Sandbox's opaque pass keeps the exact tier's shadows (mini_host has only those).
TEST(MiniHost, TheFastTiersEdgesComposeAsInNimbus) {
    TempFolder folder;
    const std::string scene = withoutTextures("cumulus_aircraft", folder);
    const std::string mini = (folder / "mini.exr").string(), nimbus = (folder / "nimbus.exr").string();
    const ProcessResult ra = runProcess(miniHost(), {scene, "--size", "256x144", "--quality", "fast", "--media-scale", "0.5", "--out", mini});
    const ProcessResult rb = runProcess(sandboxExecutable(), {"render", scene, "--size", "256x144", "--quality", "fast", "--set", "media_scale=0.5",
                                                              "--set", "shadow_map_size=2048", "--set", "pcf_radius=1", "--out", nimbus});
    ASSERT_EQ(ra.exitCode, 0) << ra.describe() << "\n" << ra.err;
    ASSERT_EQ(rb.exitCode, 0) << rb.describe() << "\n" << rb.err;
    const media::reference::ImageMetrics m = media::reference::compareImages(assets::readImage(mini), assets::readImage(nimbus));
    EXPECT_EQ(m.nonfinite, 0u);
    EXPECT_LE(m.relRmse, kImageRelRmse);
    EXPECT_LE(m.p99Abs, kImageP99);
    std::printf("[ measured ] cumulus_aircraft fast at half resolution: mini_host against sandbox rel_rmse=%.4f p99=%.4f\n", m.relRmse, m.p99Abs);
}

TEST(MiniHost, BadCommandLinesExitTwoWithOneLine) {
    TempFolder folder;
    const std::string out = (folder / "x.exr").string();
    for (const std::vector<std::string>& args : {std::vector<std::string>{content("demo"), "--out", out, "--size", "160"},
                                                 std::vector<std::string>{content("demo")},
                                                 std::vector<std::string>{content("demo"), "--out", out, "--media-scale", "2"},
                                                 std::vector<std::string>{content("demo"), "--out", out, "--depth", "inverted"},
                                                 std::vector<std::string>{content("demo"), "--out", out, "--quality", "fastest"}}) {
        const ProcessResult r = runProcess(miniHost(), args);
        EXPECT_EQ(r.exitCode, 2) << r.describe();
        EXPECT_EQ(r.errLines().size(), 1u) << r.err;
    }
}

TEST(MiniHost, ABrokenExtensionIsRefusedNamingTheField) {
    TempFolder folder;
    const std::string gltf = R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
        "extensionsUsed": ["NIMBUS_participating_media"],
        "nodes": [{"name": "fog", "extensions": {"NIMBUS_participating_media": {"medium": {"extinction": -1}}}}]})";
    const std::filesystem::path file = folder / "broken.gltf";
    FILE* f = std::fopen(file.c_str(), "w");
    ASSERT_NE(f, nullptr);
    std::fputs(gltf.c_str(), f);
    std::fclose(f);
    const ProcessResult r = runProcess(miniHost(), {file.string(), "--out", (folder / "x.exr").string()});
    EXPECT_EQ(r.exitCode, 1) << r.describe();
    ASSERT_EQ(r.errLines().size(), 1u) << r.err;
    EXPECT_NE(r.err.find("broken.gltf"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("fog"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("medium.extinction"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace nimbus::test
