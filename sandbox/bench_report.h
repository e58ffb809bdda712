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
    // The multiple model's Monte Carlo reference: its paths per pixel, and its noise as rel-RMSE
    // (the RMS of its per-pixel standard error over its mean luminance): every row's error holds it
    // in quadrature, so a row near it is as good as the judge can tell. 0 for the single model.
    int referenceSpp = 0;
    double referenceNoise = 0.0;
    std::vector<BenchResult> results;
    nlohmann::json scaling;        // --scaling: rows of {mode, particles, width, height, frame_ms}
};

nlohmann::json toJson(const BenchRun& run);
std::string markdownTable(const BenchRun& run);

// Writes bench.json, bench.csv and bench.md into `folder`, then tries the plot; returns a line
// saying where the plot went or why there is none (no python3/matplotlib is not an error).
std::string writeBenchFiles(const BenchRun& run, const std::filesystem::path& folder);

}  // namespace nimbus::sandbox
