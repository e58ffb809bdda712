#pragma once
// Per-pass GPU-synchronised timing: glFinish before and after each pass, wall clock in between.
// Synchronising costs a little throughput, so it is only used when measuring (--stats, bench).
#include <chrono>
#include <map>
#include <string>
#include <vector>

#include "nimbus/gpu/frame_graph.h"

namespace nimbus::gpu {

class GlPassTimer final : public PassTimer {
public:
    void begin(std::string_view pass) override;
    void end(std::string_view pass) override;

    // Milliseconds per pass, one entry per frame the pass ran in.
    const std::map<std::string, std::vector<double>>& samples() const { return samples_; }
    void clear() { samples_.clear(); }

private:
    std::chrono::steady_clock::time_point start_;
    std::map<std::string, std::vector<double>> samples_;
};

double median(std::vector<double> values);

}  // namespace nimbus::gpu
