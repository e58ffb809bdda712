#pragma once
// What `sandbox bench` measures: a sweep over the settings that trade speed for error, each timed
// (median of GPU-synchronised frames, per pass) and judged against one reference render.
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "nimbus/assets/image_io.h"
#include "nimbus/media/particle_set.h"
#include "nimbus/media/technique.h"
#include "nimbus/media/reference/image_metrics.h"
#include "session.h"

namespace nimbus::sandbox {

struct BenchConfig {
    std::string name;                                        // e.g. "blocks blocks=45"
    std::vector<std::pair<std::string, std::string>> settings;  // applied with Settings::set
};

// The sweep for a scene's particles: modes, slice counts, block counts around the automatic one,
// impostor resolution, instancing and media scale. `lamps`: the scene's point and spot lights
// (media::lampPositions), which the automatic block count looks at. `multiple`: the session renders
// the multiple-scattering model, whose own settings (the diffusion grid's voxels and sweeps) join.
std::vector<BenchConfig> standardSweep(const media::ParticleSet& particles, const std::vector<glm::dvec3>& lamps, bool multiple);

struct BenchResult {
    BenchConfig config;
    double frameMs = 0.0;                  // median over the timed frames
    std::map<std::string, double> passMs;  // per-pass medians (a separate, pass-synchronised run)
    double mediaMs = 0.0;                  // sum of the media passes' medians
    double floorMs = 0.0;                  // the splat floor: every particle's billboard blended once
    media::reference::ImageMetrics error;
    int slices = 0;
    std::vector<media::TechniqueStat> technique;  // what the mode reported (media_renderer.h MediaFrameStats)
    bool pareto = false;                   // on the time/error Pareto front of its sweep
};

struct BenchTiming {
    int frames = 20;  // timed frames per setting (docs/design.md §6: at least 20)
    int warmup = 3;
};

// Renders every configuration in `session` (GL context current) at width×height, against `reference`.
std::vector<BenchResult> runSweep(Session& session, const std::vector<BenchConfig>& configs, int width, int height,
                                  const assets::RgbImage& reference, const BenchTiming& timing,
                                  const std::function<void(std::size_t)>& progress);

// Marks the results no other result beats in both frame time and rel-RMSE.
void markPareto(std::vector<BenchResult>& results);

}  // namespace nimbus::sandbox
