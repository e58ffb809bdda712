// `sandbox bench` run as a user runs it: the sweep holds every mode's rows, --only picks rows of
// it, bench.json records each row's time and error and the optical model both sides used (with the
// multiple model's Monte Carlo reference, its paths and noise), and a wrong row or model is refused
// in one line before the reference's work starts.
// Tiny images: this checks what the command does, not what it measures (scripts/bench does that).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "process.h"

namespace nimbus::test {
namespace {

namespace fs = std::filesystem;

const fs::path kContent = NIMBUS_CONTENT_DIR_FOR_TESTS;

ProcessResult bench(const std::vector<std::string>& extra, const fs::path& out) {
    std::vector<std::string> args = {"bench", (kContent / "scenes/smoke.gltf").string(), "--time", "8", "--size", "48x27",
                                     "--out", out.string()};
    args.insert(args.end(), extra.begin(), extra.end());
    return runProcess(sandboxExecutable(), args);
}

TEST(SandboxBench, OneRowOfEveryModeWithTheModelRecorded) {
    TempFolder out;
    const std::vector<std::string> rows = {"fast", "blocks slices=8", "raymarch voxels=48", "sheets quality=fast", "billboards"};
    std::vector<std::string> args = {"--scattering", "single"};
    for (const std::string& row : rows) args.insert(args.end(), {"--only", row});
    const ProcessResult r = bench(args, out.path());
    ASSERT_EQ(r.exitCode, 0) << explain(r);
    std::ifstream file(out.path() / "bench.json");
    ASSERT_TRUE(file) << explain(r);
    const nlohmann::json run = nlohmann::json::parse(file);
    EXPECT_EQ(run["scattering"], "single");
    std::set<std::string> seen;
    bool anyOnFront = false;
    for (const auto& row : run["results"]) {
        seen.insert(row["setting"].get<std::string>());
        EXPECT_GT(row["frame_ms"].get<double>(), 0.0) << row["setting"];
        ASSERT_TRUE(row["rel_rmse"].is_number()) << row["setting"];
        EXPECT_TRUE(std::isfinite(row["rel_rmse"].get<double>())) << row["setting"];
        anyOnFront = anyOnFront || row["pareto"].get<bool>();
    }
    EXPECT_EQ(seen, std::set<std::string>(rows.begin(), rows.end()));
    EXPECT_TRUE(anyOnFront) << "some row is always on the Pareto front";
}

TEST(SandboxBench, TheMultipleModelsReferenceStatesItsPathsAndNoise) {
    TempFolder out;
    const ProcessResult r = bench({"--scattering", "multiple", "--spp", "8", "--only", "fast"}, out.path());
    ASSERT_EQ(r.exitCode, 0) << explain(r);
    std::ifstream file(out.path() / "bench.json");
    ASSERT_TRUE(file) << explain(r);
    const nlohmann::json run = nlohmann::json::parse(file);
    EXPECT_EQ(run["scattering"], "multiple");
    EXPECT_EQ(run["reference_spp"], 8);
    // Eight paths leave noise; the single model's reference (exact) states none.
    EXPECT_GT(run["reference_noise_rel_rmse"].get<double>(), 0.0);
    EXPECT_LT(run["reference_noise_rel_rmse"].get<double>(), 1.0);
    EXPECT_NE(r.out.find("paths per pixel"), std::string::npos) << explain(r);
    TempFolder single;
    ASSERT_EQ(bench({"--scattering", "single", "--only", "fast"}, single.path()).exitCode, 0);
    std::ifstream singleFile(single.path() / "bench.json");
    EXPECT_FALSE(nlohmann::json::parse(singleFile).contains("reference_spp"));
}

TEST(SandboxBench, RefusesAnUnknownRowOrModelInOneLine) {
    TempFolder out;
    for (const std::vector<std::string>& args : {std::vector<std::string>{"--only", "no such row"},
                                                 std::vector<std::string>{"--scattering", "nonsense"}}) {
        SCOPED_TRACE(args[0]);
        const ProcessResult r = bench(args, out.path());
        EXPECT_EQ(r.exitCode, 2) << explain(r);
        ASSERT_EQ(r.errLines().size(), 1u) << explain(r);
        EXPECT_NE(r.err.find(args[0]), std::string::npos) << explain(r);
        EXPECT_FALSE(fs::exists(out / "bench.json"));
    }
}

}  // namespace
}  // namespace nimbus::test
