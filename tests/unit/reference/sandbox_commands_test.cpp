// Tests sandbox/reference_command.cpp and sandbox/compare_command.cpp through the real executable.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <cstring>
#include <string>

#include "gltf_fixture.h"
#include "nimbus/assets/image_io.h"
#include "nimbus/assets/scene_queries.h"
#include "nimbus/media/nimbus/assets_document.h"
#include "nimbus/media/media_scene.h"
#include "nimbus/media/reference/image_metrics.h"
#include "nimbus/media/reference/reference_renderer.h"

namespace nimbus::media::test {
namespace {

struct CommandResult {
    int exitCode = -1;
    std::string output;  // stdout and stderr
};

CommandResult sandbox(const std::string& arguments) {
    CommandResult r;
    const std::string command = std::string(NIMBUS_SANDBOX_EXE) + " " + arguments + " 2>&1";
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) return r;
    std::array<char, 512> buffer{};
    while (fgets(buffer.data(), static_cast<int>(buffer.size()), pipe)) r.output += buffer.data();
    const int status = pclose(pipe);
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

// A small scene: a ground quad, a camera, a sun and a cloud of three particles.
std::filesystem::path writeScene() {
    GltfFixture f;
    const int positions = f.addFloats({-5, 0, 5, 5, 0, 5, 5, 0, -5, -5, 0, -5}, "VEC3");
    const int normals = f.addFloats({0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0}, "VEC3");
    const int indices = f.addIndices({0, 1, 2, 0, 2, 3});
    auto& root = f.root();
    nlohmann::json primitive = {{"attributes", {{"POSITION", positions}, {"NORMAL", normals}}}, {"indices", indices}};
    root["meshes"] = nlohmann::json::array({{{"primitives", nlohmann::json::array({primitive})}}});
    root["cameras"] = {{{"name", "main"}, {"type", "perspective"}, {"perspective", {{"yfov", 0.8}, {"znear", 0.1}}}}};
    root["extensionsUsed"].push_back("KHR_lights_punctual");
    root["extensions"]["KHR_lights_punctual"] = {{"lights", {{{"type", "directional"}, {"intensity", 3.0}}}}};
    root["extensions"]["NIMBUS_participating_media"] = {{"background", {0.3, 0.5, 0.8}}, {"ambient", {0.1, 0.1, 0.1}}};
    f.addNode({{"mesh", 0}});
    f.addNode({{"name", "eye"}, {"camera", 0}, {"translation", {0.0, 2.0, 8.0}}});
    f.addNode({{"name", "sun"}, {"rotation", {-0.5, 0.0, 0.0, 0.8660254}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
    f.addCloud("cloud", {0, 1.5, 0, 0.8f, 1.8f, 0.2f, -0.6f, 1.3f, 0.4f}, {1.0f, 0.8f, 0.7f},
               {{"extinction", 2.0}, {"albedo", {0.9, 0.9, 0.9}}, {"g", 0.4}});
    return f.write("scene");
}

TEST(SandboxReference, WritesTheSameImageAsTheLibrary) {
    const auto scene = writeScene();
    const auto out = scene.parent_path() / "ref.exr";
    const CommandResult r = sandbox("reference " + scene.string() + " --out " + out.string() + " --size 32x18");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("32x18, 3 particles"), std::string::npos) << r.output;
    const assets::RgbImage written = assets::readImage(out);
    ASSERT_EQ(written.width, 32);
    ASSERT_EQ(written.height, 18);

    const assets::Scene loaded = assets::loadScene(scene);
    const MediaScene media = parseMediaScene(AssetsDocument(loaded));
    const auto world = assets::computeWorldTransforms(loaded, 0.0);
    const ParticleSet particles = particlesAtTime(AssetsDocument(loaded), media, 0.0);
    reference::ReferenceInputs in;
    in.scene = &loaded;
    in.world = &world;
    in.camera = assets::resolveCamera(loaded, world, "", assets::meshBounds(loaded, world), 32.0 / 18.0);
    in.lights = assets::resolveLights(loaded, world);
    in.particles = &particles;
    reference::ReferenceSettings settings;
    settings.width = 32;
    settings.height = 18;
    settings.progress = false;
    const assets::RgbImage expected = reference::renderReference(in, settings);
    EXPECT_EQ(std::memcmp(expected.rgb.data(), written.rgb.data(), expected.rgb.size() * sizeof(float)), 0);
}

TEST(SandboxReference, RefusesBadArguments) {
    const auto scene = writeScene();
    const std::string out = (scene.parent_path() / "x.exr").string();
    for (const char* size : {"0x10", "10x", "abcxdef", "20000x10", "-4x4"}) {
        const CommandResult r = sandbox("reference " + scene.string() + " --out " + out + " --size " + std::string(size));
        EXPECT_NE(r.exitCode, 0) << size;
        EXPECT_NE(r.output.find("--size"), std::string::npos) << r.output;
    }
    EXPECT_NE(sandbox("reference " + scene.string()).exitCode, 0);  // --out is required
    const CommandResult camera = sandbox("reference " + scene.string() + " --out " + out + " --size 8x8 --camera nope");
    EXPECT_NE(camera.exitCode, 0);
    EXPECT_NE(camera.output.find("nope"), std::string::npos) << camera.output;
    const CommandResult missing = sandbox("reference /nonexistent/scene.gltf --out " + out);
    EXPECT_NE(missing.exitCode, 0);
}

TEST(SandboxCompare, PrintsExactlyTheFourMetricsAsJson) {
    const auto dir = writeScene().parent_path();
    assets::RgbImage a(16, 8), b(16, 8);
    for (std::size_t i = 0; i < a.rgb.size(); ++i) {
        b.rgb[i] = 0.25f + 0.001f * static_cast<float>(i % 17);
        a.rgb[i] = b.rgb[i] * (i % 5 == 0 ? 1.1f : 1.0f);
    }
    a.rgb[4] = std::numeric_limits<float>::quiet_NaN();
    assets::writeImage(dir / "a.exr", a);
    assets::writeImage(dir / "b.exr", b);
    const CommandResult r = sandbox("compare " + (dir / "a.exr").string() + " " + (dir / "b.exr").string() + " --json");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const nlohmann::json j = nlohmann::json::parse(r.output);
    ASSERT_EQ(j.size(), 4u) << r.output;
    const reference::ImageMetrics m = reference::compareImages(a, b);
    EXPECT_DOUBLE_EQ(j.at("rel_rmse").get<double>(), m.relRmse);
    EXPECT_DOUBLE_EQ(j.at("psnr").get<double>(), m.psnr);
    EXPECT_DOUBLE_EQ(j.at("p99_abs").get<double>(), m.p99Abs);
    EXPECT_EQ(j.at("nonfinite").get<int>(), 1);

    const CommandResult same = sandbox("compare " + (dir / "b.exr").string() + " " + (dir / "b.exr").string() + " --json");
    const nlohmann::json s = nlohmann::json::parse(same.output);
    EXPECT_EQ(s.at("rel_rmse").get<double>(), 0.0);
    EXPECT_EQ(s.at("psnr").get<double>(), 200.0);
    const CommandResult table = sandbox("compare " + (dir / "a.exr").string() + " " + (dir / "b.exr").string());
    EXPECT_EQ(table.exitCode, 0);
    EXPECT_NE(table.output.find("rel_rmse"), std::string::npos);
}

TEST(SandboxCompare, RefusesMissingFilesAndSizeMismatch) {
    const auto dir = writeScene().parent_path();
    assets::writeImage(dir / "small.exr", assets::RgbImage(4, 4));
    assets::writeImage(dir / "wide.exr", assets::RgbImage(8, 4));
    const CommandResult size = sandbox("compare " + (dir / "small.exr").string() + " " + (dir / "wide.exr").string() + " --json");
    EXPECT_NE(size.exitCode, 0);
    EXPECT_NE(size.output.find("sizes differ"), std::string::npos) << size.output;
    const CommandResult missing = sandbox("compare " + (dir / "small.exr").string() + " " + (dir / "none.exr").string());
    EXPECT_NE(missing.exitCode, 0);
    EXPECT_NE(missing.output.find("none.exr"), std::string::npos) << missing.output;
    std::FILE* junk = std::fopen((dir / "junk.exr").c_str(), "w");
    std::fputs("not an image", junk);
    std::fclose(junk);
    EXPECT_NE(sandbox("compare " + (dir / "junk.exr").string() + " " + (dir / "small.exr").string()).exitCode, 0);
}

}  // namespace
}  // namespace nimbus::media::test
