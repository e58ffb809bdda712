#include "bench_report.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <variant>

#include "nimbus/base/error.h"
#include "source_tree.h"

namespace nimbus::sandbox {
namespace {

nlohmann::json number(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

std::string fixed(double v, int digits) {
    if (!std::isfinite(v)) return "–";
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*f", digits, v);
    return buffer;
}

void writeText(const std::filesystem::path& file, const std::string& text) {
    std::ofstream out(file);
    if (!out) throwInputError(file.string(), "", "", "cannot write");
    out << text;
}

}  // namespace

nlohmann::json toJson(const BenchRun& run) {
    nlohmann::json j;
    j["scene"] = run.scene;
    j["time"] = run.time;
    j["width"] = run.width;
    j["height"] = run.height;
    j["particles"] = run.particles;
    j["gl_renderer"] = run.glRenderer;
    j["date"] = run.date;
    j["reference_seconds"] = run.referenceSeconds;
    j["scattering"] = run.scattering;
    if (run.referenceSpp > 0) {
        j["reference_spp"] = run.referenceSpp;
        j["reference_noise_rel_rmse"] = run.referenceNoise;
    }
    j["results"] = nlohmann::json::array();
    for (const auto& r : run.results) {
        nlohmann::json row;
        row["setting"] = r.config.name;
        nlohmann::json settings = nlohmann::json::object();
        for (const auto& [k, v] : r.config.settings) settings[k] = v;
        row["settings"] = settings;
        row["frame_ms"] = r.frameMs;
        row["media_ms"] = r.mediaMs;
        row["passes_ms"] = r.passMs;
        row["splat_floor_ms"] = r.floorMs;
        row["frame_over_floor"] = number(r.floorMs > 0.0 ? r.frameMs / r.floorMs : NAN);
        row["media_over_floor"] = number(r.floorMs > 0.0 ? r.mediaMs / r.floorMs : NAN);
        row["rel_rmse"] = number(r.error.relRmse);
        row["psnr"] = number(r.error.psnr);
        row["p99_abs"] = number(r.error.p99Abs);
        row["nonfinite"] = r.error.nonfinite;
        row["slices"] = r.slices;
        for (const media::TechniqueStat& t : r.technique) std::visit([&](auto v) { row[t.key] = v; }, t.value);
        row["pareto"] = r.pareto;
        j["results"].push_back(row);
    }
    if (!run.scaling.is_null()) j["scaling"] = run.scaling;
    return j;
}

std::string markdownTable(const BenchRun& run) {
    std::ostringstream md;
    if (run.referenceSpp > 0)
        md << "Reference: Monte Carlo, " << run.referenceSpp << " paths per pixel; its noise, " << fixed(100.0 * run.referenceNoise, 2)
           << "% rel-RMSE, is in every row's error (in quadrature).\n\n";
    md << "| setting | frame ms | media ms | × splat floor | rel-RMSE | PSNR dB | p99 abs | Pareto |\n";
    md << "|---|---:|---:|---:|---:|---:|---:|:-:|\n";
    for (const auto& r : run.results) {
        md << "| " << r.config.name << " | " << fixed(r.frameMs, 1) << " | " << fixed(r.mediaMs, 1) << " | "
           << (r.floorMs > 0.0 ? fixed(r.frameMs / r.floorMs, 1) : std::string("–")) << " | " << fixed(100.0 * r.error.relRmse, 2)
           << "% | " << fixed(r.error.psnr, 1) << " | " << fixed(r.error.p99Abs, 4) << " | " << (r.pareto ? "●" : "") << " |\n";
    }
    return md.str();
}

std::string writeBenchFiles(const BenchRun& run, const std::filesystem::path& folder) {
    std::filesystem::create_directories(folder);
    writeText(folder / "bench.json", toJson(run).dump(2) + "\n");
    std::ostringstream csv;
    csv << "setting,frame_ms,media_ms,splat_floor_ms,rel_rmse,psnr,p99_abs,nonfinite,slices,pareto\n";  // the modes' own figures: bench.json
    for (const auto& r : run.results)
        csv << '"' << r.config.name << "\"," << r.frameMs << ',' << r.mediaMs << ',' << r.floorMs << ',' << r.error.relRmse << ','
            << r.error.psnr << ',' << r.error.p99Abs << ',' << r.error.nonfinite << ',' << r.slices << ','
            << (r.pareto ? 1 : 0) << '\n';
    writeText(folder / "bench.csv", csv.str());
    writeText(folder / "bench.md", markdownTable(run));

    const std::filesystem::path script = sourceDirectory() / "tools" / "plot_bench.py";
    const std::string command = "/usr/bin/python3 '" + script.string() + "' '" + (folder / "bench.json").string() + "' '" +
                                (folder / "bench.png").string() + "' >/dev/null 2>&1";
    if (std::system(command.c_str()) == 0) return "plot " + (folder / "bench.png").string();
    return "no plot (needs /usr/bin/python3 with matplotlib: scripts/bootstrap installs python3-matplotlib)";
}

}  // namespace nimbus::sandbox
