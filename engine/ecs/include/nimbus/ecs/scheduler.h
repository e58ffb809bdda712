#pragma once
// Systems grouped into named phases that run in a fixed order. Default phases, in order:
// Startup (each of its systems runs once), Simulate, Prepare, Render, Present.
// Within a phase systems run in registration order, except where `after`/`before` constraints
// say otherwise: a stable topological sort that moves a system's prerequisites just ahead of it
// and keeps everything else in registration order (so it never depends on hashing or timing).
// Ordering problems (a cycle, a constraint naming no system, a system in a phase that does not
// exist) are programmer errors, reported as std::logic_error when the order is first needed.
#include <cstddef>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace nimbus::ecs {

class World;

namespace phases {
inline constexpr char kStartup[] = "Startup";
inline constexpr char kSimulate[] = "Simulate";
inline constexpr char kPrepare[] = "Prepare";
inline constexpr char kRender[] = "Render";
inline constexpr char kPresent[] = "Present";
}  // namespace phases

using SystemFn = std::function<void(World&)>;

struct SystemDesc {
    // Every member has an initialiser so that designated initialisers may leave any out
    // (GCC's -Wmissing-field-initializers stays quiet).
    std::string name{};                    // unique among all systems; required
    std::string phase = phases::kSimulate;
    std::vector<std::string> after{};      // systems this one runs after
    std::vector<std::string> before{};     // systems this one runs before
};

enum class PhaseRun {
    EveryUpdate,
    Once,  // each system of the phase runs once, on the first update after it was added
};

class Scheduler {
public:
    Scheduler();  // with the default phases

    // Adds a phase right after `after` (and after phases added after it earlier, so phases added
    // after the same one keep their registration order); an empty `after` appends at the end.
    // Returns false, changing nothing, if the phase exists. Throws if `after` does not exist.
    bool addPhase(std::string name, std::string_view after, PhaseRun run = PhaseRun::EveryUpdate);

    // Returns false, changing nothing, if a system with this name exists (adding it twice is harmless).
    // Throws for an empty name or an empty function. The phase and constraints are checked later.
    bool addSystem(SystemDesc desc, SystemFn fn);

    bool hasPhase(std::string_view name) const;
    bool hasSystem(std::string_view name) const;
    std::vector<std::string> phaseOrder() const;
    // The systems of a phase in the order they run (resolves the order: may throw).
    std::vector<std::string> systemOrder(std::string_view phase);

    // Checks every phase, constraint and cycle now, rather than at the next run.
    void resolve();

    // Runs one phase's systems (of a Once phase: those that have not run yet). Throws for an unknown phase.
    void runPhase(std::string_view phase, World& world);
    // Runs every phase in order.
    void runAll(World& world);

private:
    struct Phase {
        std::string name;
        std::string anchor;  // the phase it was added after; empty for the defaults
        PhaseRun run = PhaseRun::EveryUpdate;
        std::vector<std::size_t> order;  // resolved: indices into systems_
    };
    struct System {
        SystemDesc desc;
        SystemFn fn;
        bool ran = false;
    };

    std::size_t phaseIndex(std::string_view name) const;  // phases_.size() when absent
    std::size_t systemIndex(std::string_view name) const;  // systems_.size() when absent
    bool descendsFrom(std::size_t phase, std::string_view ancestor) const;
    void runResolvedPhase(std::size_t phase, World& world);
    void requireNotRunning(std::string_view operation) const;

    std::vector<Phase> phases_;
    std::vector<System> systems_;  // registration order
    bool resolved_ = false;
    bool running_ = false;
};

}  // namespace nimbus::ecs
