#include "nimbus/base/frame_budget.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

namespace nimbus {

FrameBudgetDesc withDefaults(FrameBudgetDesc desc) {
    if (desc.window <= 0) desc.window = 3;
    if (desc.tolerance <= 0.0) desc.tolerance = 0.1;
    return desc;
}

FrameBudget::FrameBudget(FrameBudgetDesc desc, Clock clock) : desc_(withDefaults(desc)), clock_(std::move(clock)) {
    if (!(desc_.budgetMs > 0.0) || !std::isfinite(desc_.budgetMs)) throw std::invalid_argument("the frame budget must be a positive number of milliseconds");
    if (desc_.rungs < 1) throw std::invalid_argument("a frame budget needs at least one rung");
    if (!clock_) {
        clock_ = [] {
            return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count();
        };
    }
    rung_ = desc_.rungs - 1;
    tooSlow_.assign(static_cast<std::size_t>(desc_.rungs), 0);
    median_.assign(static_cast<std::size_t>(desc_.rungs), -1.0);
    settled_ = desc_.rungs == 1;
}

void FrameBudget::beginFrame() { started_ = clock_(); }

void FrameBudget::endFrame() { record(clock_() - started_); }

void FrameBudget::record(double ms) {
    // One frame far over the budget condemns the rung at once: no need to sit through a window of them.
    if (ms > 2.0 * desc_.budgetMs) {
        judge(ms);
        return;
    }
    window_.push_back(ms);
    if (static_cast<int>(window_.size()) < desc_.window) return;
    std::vector<double> sorted = window_;
    std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2), sorted.end());
    judge(sorted[sorted.size() / 2]);
}

void FrameBudget::judge(double median) {
    window_.clear();
    const auto r = static_cast<std::size_t>(rung_);
    median_[r] = median;
    const bool fits = median <= desc_.budgetMs * (settled_ ? 1.0 + desc_.tolerance : 1.0);
    if (!fits) {
        tooSlow_[r] = 1;
        if (rung_ + 1 < desc_.rungs) {
            moveTo(rung_ + 1);
            settled_ = tooSlow_[r + 1] == 0 && median_[r + 1] >= 0.0;  // back to a rung already known to fit
        } else {
            settled_ = true;  // even the fastest rung does not fit: it is the best there is
        }
        return;
    }
    if (settled_) return;
    if (rung_ > 0 && tooSlow_[r - 1] == 0) {
        moveTo(rung_ - 1);
        return;
    }
    settled_ = true;
}

void FrameBudget::moveTo(int rung) {
    rung_ = rung;
    window_.clear();
}

double FrameBudget::medianMs(int rung) const {
    if (rung < 0 || rung >= desc_.rungs) return -1.0;
    return median_[static_cast<std::size_t>(rung)];
}

}  // namespace nimbus
