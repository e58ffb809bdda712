#pragma once
// A progress bar for long work (reference renders, benchmarks). Draws on stderr only when stderr
// is a terminal, so logs and CI output stay clean. Safe to advance from several threads.
#include <atomic>
#include <chrono>
#include <cstddef>
#include <mutex>
#include <string>

namespace nimbus {

class ProgressBar {
public:
    ProgressBar(std::string label, std::size_t total);
    ~ProgressBar();
    ProgressBar(const ProgressBar&) = delete;
    ProgressBar& operator=(const ProgressBar&) = delete;

    void advance(std::size_t steps = 1);
    void finish();
    bool visible() const { return visible_; }

private:
    void draw(std::size_t done);

    std::string label_;
    std::size_t total_;
    std::atomic<std::size_t> done_{0};
    bool visible_;
    bool finished_ = false;
    std::mutex drawMutex_;
    std::chrono::steady_clock::time_point start_;
    std::chrono::steady_clock::time_point lastDraw_;
};

}  // namespace nimbus
