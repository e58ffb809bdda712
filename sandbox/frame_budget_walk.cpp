#include "frame_budget_walk.h"

#include <chrono>
#include <set>

#include <epoxy/gl.h>

#include "nimbus/base/frame_budget.h"
#include "nimbus/base/settings.h"
#include "nimbus/media/ecs/media_plugin.h"

namespace nimbus::sandbox {
namespace {

void applyRung(Settings& settings, const media::ecs::QualityRung& rung, const std::set<std::string>& userKeys) {
    for (const auto& r : media::ecs::kQualityLadder)
        for (const auto& [key, value] : r.assignments())
            if (!userKeys.count(key)) settings.unset(key);
    for (const auto& [key, value] : rung.assignments())
        if (!userKeys.count(key)) settings.set(key, value, std::string("--budget-ms (") + rung.name + ")");
}

}  // namespace

BudgetChoice settleOnBudget(ecs::App& app, double budgetMs, int maxFrames) {
    auto& settings = app.resource<Settings>();
    std::set<std::string> userKeys;
    for (const auto& rung : media::ecs::kQualityLadder)
        for (const auto& [key, value] : rung.assignments())
            if (settings.has(key) && settings.origin(key) != "sandbox's default") userKeys.insert(key);
    const int rungs = static_cast<int>(std::size(media::ecs::kQualityLadder));
    FrameBudget budget({.budgetMs = budgetMs, .rungs = rungs});
    BudgetChoice choice;
    int applied = -1;
    while (!budget.settled() && choice.framesRendered < maxFrames) {
        if (budget.rung() != applied) {
            applied = budget.rung();
            applyRung(settings, media::ecs::kQualityLadder[applied], userKeys);
            app.runPhase(ecs::phases::kPrepare);  // a new setting's first frame builds its programs: not timed
            app.runPhase(ecs::phases::kRender);
            app.runPhase(ecs::phases::kPresent);
        }
        glFinish();
        budget.beginFrame();
        app.runPhase(ecs::phases::kPrepare);
        app.runPhase(ecs::phases::kRender);
        app.runPhase(ecs::phases::kPresent);
        glFinish();
        budget.endFrame();
        ++choice.framesRendered;
    }
    if (budget.rung() != applied) applyRung(settings, media::ecs::kQualityLadder[budget.rung()], userKeys);
    choice.rung = media::ecs::kQualityLadder[budget.rung()].name;
    choice.medianMs = budget.medianMs(budget.rung());
    return choice;
}

}  // namespace nimbus::sandbox
