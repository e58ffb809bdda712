#pragma once
// `sandbox render --budget-ms B`: renders frames while a FrameBudget walks the quality ladder
// (media_plugin.h kQualityLadder), until it settles on the lowest-error rung whose frames fit B.
#include <string>

#include "nimbus/ecs/app.h"

namespace nimbus::sandbox {

struct BudgetChoice {
    std::string rung;         // the ladder rung's name
    double medianMs = 0.0;    // the settled rung's frames while judging it
    int framesRendered = 0;   // while walking
};

// Applies each rung's settings to the app's Settings (keys the user set stay as set) and renders
// GPU-synchronised frames until the controller settles, at most `maxFrames`. Leaves the chosen
// rung applied. Needs a current GL context.
BudgetChoice settleOnBudget(ecs::App& app, double budgetMs, int maxFrames = 120);

}  // namespace nimbus::sandbox
