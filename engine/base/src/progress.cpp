#include "nimbus/base/progress.h"

#include <cstdio>
#include <unistd.h>

namespace nimbus {

ProgressBar::ProgressBar(std::string label, std::size_t total)
    : label_(std::move(label)), total_(total == 0 ? 1 : total), visible_(isatty(STDERR_FILENO) != 0),
      start_(std::chrono::steady_clock::now()), lastDraw_(start_) {}

ProgressBar::~ProgressBar() { finish(); }

void ProgressBar::advance(std::size_t steps) {
    const std::size_t done = done_.fetch_add(steps) + steps;
    if (!visible_) return;
    const auto now = std::chrono::steady_clock::now();
    std::unique_lock lock(drawMutex_, std::try_to_lock);
    if (!lock.owns_lock()) return;  // another thread is drawing; skipping a frame is harmless
    if (now - lastDraw_ < std::chrono::milliseconds(100) && done < total_) return;
    lastDraw_ = now;
    draw(done);
}

void ProgressBar::finish() {
    std::lock_guard lock(drawMutex_);
    if (finished_ || !visible_) {
        finished_ = true;
        return;
    }
    draw(total_);
    std::fputc('\n', stderr);
    finished_ = true;
}

void ProgressBar::draw(std::size_t done) {
    constexpr int kWidth = 32;
    const double fraction = done >= total_ ? 1.0 : static_cast<double>(done) / static_cast<double>(total_);
    const int filled = static_cast<int>(fraction * kWidth);
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    char bar[kWidth + 1];
    for (int i = 0; i < kWidth; ++i) bar[i] = i < filled ? '#' : '.';
    bar[kWidth] = '\0';
    std::fprintf(stderr, "\r%s [%s] %5.1f%%  %.1fs", label_.c_str(), bar, fraction * 100.0, elapsed);
    std::fflush(stderr);
}

}  // namespace nimbus
