#pragma once
// Per-pass GPU-synchronised timing: glFinish before and after each pass, wall clock in between.
// Synchronising costs a little throughput, so it is only used when measuring (--stats, bench).
#include <chrono>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "nimbus/render/frame_graph.h"

namespace nimbus::render {

class GlPassTimer final : public PassTimer {
public:
    // With `countFragments`, each pass also runs inside a GL_SAMPLES_PASSED query: the fragments it
    // wrote (what the fill-rate floor of `sandbox bench` is measured against).
    explicit GlPassTimer(bool countFragments = false) : countFragments_(countFragments) {}
    void begin(std::string_view pass) override;
    void end(std::string_view pass) override;

    // Milliseconds per pass, one entry per frame the pass ran in.
    const std::map<std::string, std::vector<double>>& samples() const { return samples_; }
    // Fragments written per pass, one entry per frame (empty without countFragments).
    const std::map<std::string, std::vector<std::uint64_t>>& fragments() const { return fragments_; }
    void clear() {
        samples_.clear();
        fragments_.clear();
    }

private:
    bool countFragments_;
    gpu::Query query_;
    std::chrono::steady_clock::time_point start_;
    std::map<std::string, std::vector<double>> samples_;
    std::map<std::string, std::vector<std::uint64_t>> fragments_;
};

double median(std::vector<double> values);

}  // namespace nimbus::render
