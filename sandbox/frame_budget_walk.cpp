#include "frame_budget_walk.h"

#include <chrono>
#include <map>
#include <set>

#include <epoxy/gl.h>

#include "nimbus/base/frame_budget.h"
#include "nimbus/base/error.h"
#include "nimbus/base/settings.h"
#include "nimbus/scene/scene_plugin.h"
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

// A key the user set must act on at least one rung the walk may keep (media::idleSettings): one
// that acts on none is refused before any frame is timed.
void refuseIdleOnEveryRung(ecs::App& app, const std::set<std::string>& userKeys) {
    const auto* asset = app.world().tryResource<scene::SceneAsset>();
    const bool multiple = asset == nullptr || asset->scene == nullptr || asset->scene->environment.scattering == assets::Scattering::Multiple;
    const auto& table = app.resource<media::ecs::MediaTechniques>().table;
    std::map<std::string, std::string> idleEverywhere;  // key → why, on the first rung
    bool first = true;
    for (const auto& rung : media::ecs::kQualityLadder) {
        Settings settings = app.resource<Settings>();
        applyRung(settings, rung, userKeys);
        std::map<std::string, std::string> idle;
        for (const media::IdleSetting& i : media::idleSettings(settings, table, multiple))
            if (!settings.isDefault(i.key) && (first || idleEverywhere.count(i.key))) idle[i.key] = i.why;
        idleEverywhere = std::move(idle);
        first = false;
    }
    if (!idleEverywhere.empty()) {
        const auto& [key, why] = *idleEverywhere.begin();
        throwInputError(app.resource<Settings>().origin(key), key, "", why + ", nor on any other rung --budget-ms may keep");
    }
}

}  // namespace

BudgetChoice settleOnBudget(ecs::App& app, double budgetMs, int maxFrames) {
    auto& settings = app.resource<Settings>();
    std::set<std::string> userKeys;
    for (const auto& rung : media::ecs::kQualityLadder)
        for (const auto& [key, value] : rung.assignments())
            if (settings.has(key) && settings.origin(key) != "sandbox's default") userKeys.insert(key);
    refuseIdleOnEveryRung(app, userKeys);
    const int rungs = static_cast<int>(std::size(media::ecs::kQualityLadder));
    FrameBudget budget({.budgetMs = budgetMs, .rungs = rungs});
    BudgetChoice choice;
    int applied = -1;
    while (!budget.settled() && choice.framesRendered < maxFrames) {
        if (budget.rung() != applied) {
            applied = budget.rung();
            applyRung(settings, media::ecs::kQualityLadder[applied], userKeys);
            app.redraw();  // a new setting's first frame builds its programs: not timed
        }
        glFinish();
        budget.beginFrame();
        app.redraw();
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
