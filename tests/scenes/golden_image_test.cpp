// The demo scene rendered by `sandbox render` matches tests/golden/demo_320x180.exr within the
// tolerance of golden_compare.h (tests/golden/README.md says how the golden was made and why the
// tolerance is what it is). Two more renders show what the tolerance means: a camera moved by a
// small fraction of a pixel passes, a sun 2% brighter fails.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "golden_compare.h"
#include "process.h"

namespace nimbus::test {
namespace {

namespace fs = std::filesystem;

const fs::path kDemo = fs::path(NIMBUS_CONTENT_DIR_FOR_TESTS) / "scenes/demo.gltf";
const fs::path kGolden = fs::path(NIMBUS_GOLDEN_DIR) / "demo_320x180.exr";

assets::RgbImage renderDemo(const fs::path& scene, const fs::path& out) {
    const ProcessResult r = runProcess(sandboxExecutable(), {"render", scene.string(), "--size", "320x180", "--out", out.string()});
    EXPECT_FALSE(r.signaled) << r.describe() << "\n" << r.err;
    EXPECT_EQ(r.exitCode, 0) << r.err;
    if (!fs::exists(out)) throw std::runtime_error("sandbox wrote no image: " + r.err);
    return assets::readImage(out);
}

// A copy of demo.gltf (with its .bin and textures beside it) changed by `edit`.
fs::path editedDemo(const TempFolder& folder, const std::function<void(nlohmann::json&)>& edit) {
    std::ifstream in(kDemo);
    nlohmann::json gltf = nlohmann::json::parse(in);
    edit(gltf);
    for (const char* array : {"buffers", "images"})
        for (const auto& file : gltf.value(array, nlohmann::json::array())) {
            const fs::path uri = file.at("uri").get<std::string>();
            fs::create_directories((folder / uri).parent_path());
            fs::copy_file(kDemo.parent_path() / uri, folder / uri);
        }
    const fs::path file = folder / "demo_edited.gltf";
    std::ofstream(file) << gltf.dump();
    return file;
}

TEST(GoldenImage, DemoSceneMatchesTheGolden) {
    ASSERT_TRUE(fs::exists(kGolden)) << kGolden;
    TempFolder out;
    const assets::RgbImage actual = renderDemo(kDemo, out / "demo.exr");
    const assets::RgbImage golden = assets::readImage(kGolden);
    ASSERT_EQ(actual.width, golden.width);
    ASSERT_EQ(actual.height, golden.height);
    const GoldenComparison c = compareWithGolden(actual, golden);
    RecordProperty("golden_rel_rmse", std::to_string(c.whole.relRmse));
    RecordProperty("golden_outliers", std::to_string(c.outliers));
    if (!c.passes()) {
        // Keep the image for a look (sandbox compare, oiiotool) or, after review, as the new golden.
        const fs::path kept = fs::path(NIMBUS_TEST_OUTPUT_DIR) / "demo_320x180.actual.exr";
        fs::copy_file(out / "demo.exr", kept, fs::copy_options::overwrite_existing);
        ADD_FAILURE() << "differs from the golden: " << c.describe() << "\nrendered image kept at " << kept
                      << "\n(tests/golden/README.md says when and how to regenerate the golden)";
    }
}

TEST(GoldenImage, ToleranceAcceptsASubPixelCameraShift) {
    // 2 mm sideways at ~15 m is about 1/25 of a pixel: only edge pixels may change.
    TempFolder out;
    const fs::path scene = editedDemo(out, [](nlohmann::json& g) {
        for (auto& node : g.at("nodes"))
            if (node.contains("camera")) node.at("translation")[0] = node.at("translation")[0].get<double>() + 0.002;
    });
    const GoldenComparison c = compareWithGolden(renderDemo(scene, out / "shifted.exr"), assets::readImage(kGolden));
    EXPECT_TRUE(c.passes()) << c.describe();
    EXPECT_GT(c.outliers, 0u) << "the shift should move some edge pixels, or this case shows nothing: " << c.describe();
}

TEST(GoldenImage, ToleranceRejectsATwoPercentBrighterSun) {
    TempFolder out;
    const fs::path scene = editedDemo(out, [](nlohmann::json& g) {
        auto& light = g.at("extensions").at("KHR_lights_punctual").at("lights")[0];
        light.at("intensity") = light.at("intensity").get<double>() * 1.02;
    });
    const GoldenComparison c = compareWithGolden(renderDemo(scene, out / "brighter.exr"), assets::readImage(kGolden));
    EXPECT_FALSE(c.passes()) << c.describe();
}

}  // namespace
}  // namespace nimbus::test
