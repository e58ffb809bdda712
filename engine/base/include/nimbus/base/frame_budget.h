#pragma once
// A frame-time budget, the way games drive dynamic resolution: the host renders with the rung the
// controller names, reports each frame, and the controller walks a ladder of settings ordered from
// the lowest error (rung 0) to the fastest (the last) until it settles on the lowest-error rung
// whose frames fit the budget.
//
// The walk starts at the fastest rung, so no frame is slower than the cheapest setting needs, and
// climbs one rung at a time while the frames fit. A rung whose frames do not fit (the median of a
// window, or any one frame over twice the budget) is marked and left for the next faster one; once
// the walk stops, the controller is settled and only steps down again if that rung's frames stop
// fitting by more than `tolerance`.
//
// Does not: know what a rung means, render, or read a clock itself unless given none (tests inject one).
#include <functional>
#include <vector>

namespace nimbus {

// Zero values take the defaults noted.
struct FrameBudgetDesc {
    double budgetMs = 0.0;   // required, > 0
    int rungs = 0;           // required, ≥ 1
    int window = 0;          // frames whose median judges a rung; 0: 3
    double tolerance = 0.0;  // settled: step down once the median exceeds the budget by this share; 0: 0.1
};
FrameBudgetDesc withDefaults(FrameBudgetDesc desc);

class FrameBudget {
public:
    using Clock = std::function<double()>;  // monotonic milliseconds

    // Throws std::invalid_argument for a budget that is not a positive number or no rungs.
    explicit FrameBudget(FrameBudgetDesc desc, Clock clock = {});

    int rung() const { return rung_; }  // the rung to render the next frame with
    bool settled() const { return settled_; }

    // Time one frame with the clock...
    void beginFrame();
    void endFrame();
    // ...or report its duration directly.
    void record(double ms);

    // The median of the frames judged at `rung`, or a negative value when none was.
    double medianMs(int rung) const;

private:
    void judge(double median);
    void moveTo(int rung);

    FrameBudgetDesc desc_;
    Clock clock_;
    double started_ = 0.0;
    int rung_;
    bool settled_ = false;
    std::vector<double> window_;
    std::vector<char> tooSlow_;
    std::vector<double> median_;
};

}  // namespace nimbus
