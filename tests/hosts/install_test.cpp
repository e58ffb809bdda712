// The media plugin as a package, used the way a host in its own repository uses it:
// `cmake --install` into a fresh prefix, mini_host's sources copied out of the tree, configured and
// built against that prefix alone with find_package(NimbusMedia CONFIG), then run on a content
// scene. Its image must be `sandbox render`'s within mini_host's own bound, and nothing installed
// or built may name the source tree: the plugin finds its shaders without it.
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <iostream>
#include <sstream>

#include "../scenes/process.h"
#include "nimbus/assets/image_io.h"
#include "nimbus/media/reference/image_metrics.h"

namespace nimbus::test {
namespace {

namespace fs = std::filesystem;

constexpr double kImageRelRmse = 1e-6;  // mini_host_tests' bound against sandbox render

std::string fileBytes(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// Runs a command, failing the test with its output when it fails; returns the seconds it took.
double run(const fs::path& program, const std::vector<std::string>& args, const char* what) {
    const auto start = std::chrono::steady_clock::now();
    const ProcessResult r = runProcess(program, args);
    EXPECT_EQ(r.exitCode, 0) << what << ": " << r.describe() << "\n" << r.out << "\n" << r.err;
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Every regular file under `folder` whose bytes contain `text`.
std::vector<fs::path> filesNaming(const fs::path& folder, const std::string& text) {
    std::vector<fs::path> found;
    for (const auto& entry : fs::recursive_directory_iterator(folder))
        if (entry.is_regular_file() && fileBytes(entry.path()).find(text) != std::string::npos) found.push_back(entry.path());
    return found;
}

std::uintmax_t folderBytes(const fs::path& folder) {
    std::uintmax_t bytes = 0;
    for (const auto& entry : fs::recursive_directory_iterator(folder))
        if (entry.is_regular_file()) bytes += entry.file_size();
    return bytes;
}

TEST(InstalledPlugin, AnOutOfTreeHostFindsItAndRendersAContentScene) {
    TempFolder dir;
    const fs::path prefix = dir / "prefix", source = dir / "host", build = dir / "host_build";
    const double install = run(NIMBUS_CMAKE_COMMAND, {"--install", NIMBUS_BUILD_DIR, "--prefix", prefix.string()}, "cmake --install");
    for (const char* file : {"include/nimbus/media/host.h", "include/nimbus/media/media_scene.h", "include/nimbus/gpu/view.h",
                             "include/nimbus/base/error.h", "lib/libnimbus_media_gpu.a", "lib/libnimbus_gpu.a",
                             "share/nimbus/shaders/media/host/light_transmittance.glsl", "share/nimbus/shaders/common/upsample.glsl",
                             "lib/cmake/NimbusMedia/NimbusMediaConfig.cmake", "lib/cmake/NimbusMedia/NimbusMediaConfigVersion.cmake"})
        EXPECT_TRUE(fs::exists(prefix / file)) << file << " is not installed";

    fs::copy(MINI_HOST_SOURCE_DIR, source, fs::copy_options::recursive);
    const double configure = run(NIMBUS_CMAKE_COMMAND, {"-S", source.string(), "-B", build.string(), "-G", NIMBUS_CMAKE_GENERATOR,
                                                        "-DCMAKE_CXX_COMPILER=" NIMBUS_CXX_COMPILER, "-DCMAKE_BUILD_TYPE=Release",
                                                        "-DCMAKE_PREFIX_PATH=" + prefix.string()},
                                 "configuring mini_host against the installed plugin");
    const double compile = run(NIMBUS_CMAKE_COMMAND, {"--build", build.string(), "-j", "2"}, "building mini_host");
    ASSERT_FALSE(HasFailure());

    const std::string scene = std::string(NIMBUS_CONTENT_DIR_FOR_TESTS) + "/scenes/cumulus_aircraft.gltf";
    const fs::path host = dir / "host.exr", sandbox = dir / "sandbox.exr";
    run(build / "mini_host", {scene, "--size", "256x144", "--out", host.string()}, "the out-of-tree mini_host");
    run(sandboxExecutable(), {"render", scene, "--size", "256x144", "--quality", "exact", "--out", sandbox.string()}, "sandbox render");
    ASSERT_FALSE(HasFailure());
    const auto m = media::reference::compareImages(assets::readImage(host), assets::readImage(sandbox));
    EXPECT_EQ(m.nonfinite, 0u);
    EXPECT_LE(m.relRmse, kImageRelRmse);

    // Neither the package nor the host built from it knows where Nimbus's sources are.
    EXPECT_EQ(filesNaming(prefix, NIMBUS_SOURCE_DIR_FOR_TESTS), std::vector<fs::path>{});
    EXPECT_EQ(fileBytes(build / "mini_host").find(NIMBUS_SOURCE_DIR_FOR_TESTS), std::string::npos);
    std::cout << "installed " << folderBytes(prefix) / 1024 << " KiB in " << install << " s; mini_host configured in " << configure
              << " s and built in " << compile << " s; rel_rmse " << m.relRmse << " against sandbox render\n";
}

}  // namespace
}  // namespace nimbus::test
