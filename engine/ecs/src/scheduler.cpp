#include "nimbus/ecs/scheduler.h"

#include <algorithm>
#include <stdexcept>

#include "nimbus/base/log.h"
#include "nimbus/ecs/detail/message.h"

namespace nimbus::ecs {
namespace {

using detail::message;
using detail::quoted;

// Clears a flag when a run ends, also by an exception from a system.
class RunningGuard {
public:
    explicit RunningGuard(bool& flag) : flag_(flag) { flag_ = true; }
    ~RunningGuard() { flag_ = false; }
    RunningGuard(const RunningGuard&) = delete;
    RunningGuard& operator=(const RunningGuard&) = delete;

private:
    bool& flag_;
};

}  // namespace

Scheduler::Scheduler() {
    phases_.push_back({phases::kStartup, {}, PhaseRun::Once, {}});
    for (const char* name : {phases::kSimulate, phases::kPrepare, phases::kRender, phases::kPresent})
        phases_.push_back({name, {}, PhaseRun::EveryUpdate, {}});
}

std::size_t Scheduler::phaseIndex(std::string_view name) const {
    auto it = std::find_if(phases_.begin(), phases_.end(), [&](const Phase& p) { return p.name == name; });
    return static_cast<std::size_t>(it - phases_.begin());
}

std::size_t Scheduler::systemIndex(std::string_view name) const {
    auto it = std::find_if(systems_.begin(), systems_.end(), [&](const System& s) { return s.desc.name == name; });
    return static_cast<std::size_t>(it - systems_.begin());
}

bool Scheduler::hasPhase(std::string_view name) const { return phaseIndex(name) < phases_.size(); }
bool Scheduler::hasSystem(std::string_view name) const { return systemIndex(name) < systems_.size(); }

std::vector<std::string> Scheduler::phaseOrder() const {
    std::vector<std::string> names;
    for (const Phase& p : phases_) names.push_back(p.name);
    return names;
}

void Scheduler::requireNotRunning(std::string_view operation) const {
    if (running_)
        throw std::logic_error(message({"Scheduler::", operation,
                                        ": not allowed while systems run (add phases and systems in a plugin's build)"}));
}

bool Scheduler::descendsFrom(std::size_t phase, std::string_view ancestor) const {
    // Anchors form chains back to a default phase; phases_ is small, so walking them is fine.
    for (std::string_view anchor = phases_[phase].anchor; !anchor.empty();) {
        if (anchor == ancestor) return true;
        const std::size_t i = phaseIndex(anchor);
        if (i == phases_.size()) return false;
        anchor = phases_[i].anchor;
    }
    return false;
}

bool Scheduler::addPhase(std::string name, std::string_view after, PhaseRun run) {
    requireNotRunning("addPhase");
    if (name.empty()) throw std::logic_error("Scheduler::addPhase: a phase needs a name");
    if (hasPhase(name)) return false;
    std::size_t pos = phases_.size();
    if (!after.empty()) {
        const std::size_t anchor = phaseIndex(after);
        if (anchor == phases_.size())
            throw std::logic_error(message({"Scheduler::addPhase: phase ", quoted(name), " is to follow phase ",
                                            quoted(after), ", which does not exist"}));
        pos = anchor + 1;
        while (pos < phases_.size() && descendsFrom(pos, after)) ++pos;
    }
    phases_.insert(phases_.begin() + static_cast<std::ptrdiff_t>(pos), Phase{std::move(name), std::string(after), run, {}});
    resolved_ = false;
    return true;
}

bool Scheduler::addSystem(SystemDesc desc, SystemFn fn) {
    requireNotRunning("addSystem");
    if (desc.name.empty()) throw std::logic_error("Scheduler::addSystem: a system needs a name");
    if (!fn) throw std::logic_error(message({"Scheduler::addSystem: system ", quoted(desc.name), " has no function"}));
    if (hasSystem(desc.name)) {
        log::debug(message({"Scheduler: system ", quoted(desc.name),
                            " is already registered; the second registration is ignored"}));
        return false;
    }
    systems_.push_back(System{std::move(desc), std::move(fn), false});
    resolved_ = false;
    return true;
}

void Scheduler::resolve() {
    if (resolved_) return;
    const std::size_t n = systems_.size();
    std::vector<std::size_t> phaseOf(n);
    for (std::size_t s = 0; s < n; ++s) {
        phaseOf[s] = phaseIndex(systems_[s].desc.phase);
        if (phaseOf[s] == phases_.size())
            throw std::logic_error(message({"Scheduler: system ", quoted(systems_[s].desc.name), " is in phase ",
                                            quoted(systems_[s].desc.phase),
                                            ", which does not exist (add it with addPhase)"}));
    }

    // Only constraints inside a phase matter, since phases already
    // order everything across them. A cross-phase constraint that agrees with the phase order is
    // satisfied; one that contradicts it can never be, and is reported.
    std::vector<std::vector<std::size_t>> predecessors(n);  // of each system, inside its phase
    for (std::size_t s = 0; s < n; ++s) {
        for (bool runsAfter : {true, false}) {
            for (const std::string& other : runsAfter ? systems_[s].desc.after : systems_[s].desc.before) {
                const std::string relation = runsAfter ? "after" : "before";
                const std::size_t o = systemIndex(other);
                if (o == n)
                    throw std::logic_error(message({"Scheduler: system ", quoted(systems_[s].desc.name), " must run ",
                                                    relation, " ", quoted(other), ", but no system has that name"}));
                const std::size_t first = runsAfter ? o : s;
                const std::size_t second = runsAfter ? s : o;
                if (phaseOf[first] == phaseOf[second]) {
                    predecessors[second].push_back(first);
                } else if (phaseOf[first] > phaseOf[second]) {
                    throw std::logic_error(message({"Scheduler: system ", quoted(systems_[s].desc.name), " (phase ",
                                                    quoted(systems_[s].desc.phase), ") must run ", relation, " ",
                                                    quoted(other), ", which is in the ",
                                                    runsAfter ? "later" : "earlier", " phase ",
                                                    quoted(systems_[o].desc.phase)}));
                }
            }
        }
    }

    // Depth-first, in registration order: each system is placed after its prerequisites, which are
    // pulled forward just ahead of it. Unconstrained systems keep registration order, and the result
    // depends on nothing but the registrations.
    for (std::vector<std::size_t>& preds : predecessors) {
        std::sort(preds.begin(), preds.end());
        preds.erase(std::unique(preds.begin(), preds.end()), preds.end());
    }
    for (Phase& p : phases_) p.order.clear();
    enum class Mark : unsigned char { Unvisited, OnStack, Placed };
    std::vector<Mark> mark(n, Mark::Unvisited);
    std::vector<std::size_t> stack;
    auto visit = [&](auto& self, std::size_t s) -> void {
        if (mark[s] == Mark::Placed) return;
        if (mark[s] == Mark::OnStack) {
            // stack holds s, then a prerequisite of s, then one of that, ... up to the system needing s:
            // read backwards from the top, it is the cycle in running order. Start it at the
            // earliest-registered member so the message does not depend on where the search began.
            std::vector<std::size_t> cycle(stack.rbegin(), std::find(stack.rbegin(), stack.rend(), s) + 1);
            std::rotate(cycle.begin(), std::min_element(cycle.begin(), cycle.end()), cycle.end());
            std::string text;
            for (std::size_t member : cycle) text.append(quoted(systems_[member].desc.name)).append(" -> ");
            text.append(quoted(systems_[cycle.front()].desc.name));
            throw std::logic_error(message({"Scheduler: phase ", quoted(systems_[s].desc.phase),
                                            ": ordering constraints form a cycle (x -> y: x must run before y): ",
                                            text}));
        }
        mark[s] = Mark::OnStack;
        stack.push_back(s);
        for (std::size_t pred : predecessors[s]) self(self, pred);
        stack.pop_back();
        mark[s] = Mark::Placed;
        phases_[phaseOf[s]].order.push_back(s);
    };
    for (std::size_t s = 0; s < n; ++s) visit(visit, s);
    resolved_ = true;
}

std::vector<std::string> Scheduler::systemOrder(std::string_view phase) {
    const std::size_t ph = phaseIndex(phase);
    if (ph == phases_.size()) throw std::logic_error(message({"Scheduler::systemOrder: no phase ", quoted(phase)}));
    resolve();
    std::vector<std::string> names;
    for (std::size_t s : phases_[ph].order) names.push_back(systems_[s].desc.name);
    return names;
}

void Scheduler::runResolvedPhase(std::size_t ph, World& world) {
    const bool once = phases_[ph].run == PhaseRun::Once;
    for (std::size_t s : phases_[ph].order) {
        System& system = systems_[s];
        if (once && system.ran) continue;
        system.fn(world);
        system.ran = true;
    }
}

void Scheduler::runPhase(std::string_view phase, World& world) {
    requireNotRunning("runPhase");
    const std::size_t ph = phaseIndex(phase);
    if (ph == phases_.size()) throw std::logic_error(message({"Scheduler::runPhase: no phase ", quoted(phase)}));
    resolve();
    RunningGuard guard(running_);
    runResolvedPhase(ph, world);
}

void Scheduler::runAll(World& world) {
    requireNotRunning("runAll");
    resolve();
    RunningGuard guard(running_);
    for (std::size_t ph = 0; ph < phases_.size(); ++ph) runResolvedPhase(ph, world);
}

}  // namespace nimbus::ecs
