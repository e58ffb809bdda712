#pragma once
// The files `sandbox bench` writes: bench.json (everything), bench.csv (one row per setting),
// bench.md (the Markdown table docs/PERFORMANCE.md includes) and bench.png (time against error,
// Pareto front marked, drawn by tools/plot_bench.py with Debian's matplotlib).
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bench_sweep.h"

namespace nimbus::sandbox {

struct BenchRun {
    std::string scene;
    double time = 0.0;
    int width = 0, height = 0;
    std::size_t particles = 0;
    std::string glRenderer;
    std::string date;              // ISO 8601, UTC
    double referenceSeconds = 0.0;
    std::string scattering;        // the optical model both the frames and the reference used
    std::vector<BenchResult> results;
    nlohmann::json scaling;        // --scaling: rows of {mode, particles, width, height, frame_ms}
};

nlohmann::json toJson(const BenchRun& run);
std::string markdownTable(const BenchRun& run);

// Writes bench.json, bench.csv and bench.md into `folder`, then tries the plot; returns a line
// saying where the plot went or why there is none (no python3/matplotlib is not an error).
std::string writeBenchFiles(const BenchRun& run, const std::filesystem::path& folder);

}  // namespace nimbus::sandbox
