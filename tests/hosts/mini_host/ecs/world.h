#pragma once
// mini_host's ECS: archetype tables (table.h), queries that walk the matching tables column by
// column, systems registered into fixed phases, singletons, and modules.
//
//   struct MyModule { static void import(World& w) {
//       w.component<Velocity>();
//       w.system("my.move", Phase::OnUpdate, [](World& w) {
//           w.each<Position, Velocity>([](Entity, Position& p, Velocity& v) { p.x += v.x; });
//       });
//   } };
//   World world;  world.import<MyModule>();  world.progress();
//
// Does not: allow adding or removing components inside each() (collect the entities first), run
// systems in parallel, or keep component ids stable across worlds.
#include <array>
#include <functional>
#include <map>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>
#include <tuple>
#include <typeindex>
#include <unordered_map>
#include <utility>
#include <vector>

#include "ecs/table.h"

namespace mini::ecs {

// Systems run phase by phase in this order, and within a phase in the order they were registered.
enum class Phase { OnLoad, PostLoad, OnUpdate, PreStore, OnStore };
inline constexpr std::array kPhases = {Phase::OnLoad, Phase::PostLoad, Phase::OnUpdate, Phase::PreStore, Phase::OnStore};
const char* phaseName(Phase phase);

class World;
struct System {
    std::string name;
    Phase phase;
    std::function<void(World&)> run;
};

class World {
public:
    World();
    ~World();
    World(const World&) = delete;
    World& operator=(const World&) = delete;

    // ---- entities and components ----
    Entity entity();
    void destroy(Entity e);
    bool alive(Entity e) const { return e < records_.size() && records_[e].table != nullptr; }

    // The id of component type T in this world, registering it on first use.
    template <class T>
    ComponentId component() {
        const auto [it, added] = componentIds_.try_emplace(std::type_index(typeid(T)), static_cast<ComponentId>(emptyColumns_.size()));
        if (added) emptyColumns_.push_back(std::make_unique<TypedColumn<T>>());
        return it->second;
    }

    // Sets T on e, moving e to the table with T when it had none.
    template <class T>
    T& add(Entity e, T value) {
        const ComponentId id = component<T>();
        if (T* existing = get<T>(e)) return *existing = std::move(value);
        Table& to = neighbour(*record(e).table, id, true);
        moveEntity(e, to);
        auto& column = to.values<T>(id);
        column.push_back(std::move(value));
        return column.back();
    }
    template <class T>
    void remove(Entity e) {
        const ComponentId id = component<T>();
        if (record(e).table->has(id)) moveEntity(e, neighbour(*record(e).table, id, false));
    }
    template <class T>
    T* get(Entity e) {
        const Record& r = record(e);
        const ComponentId id = component<T>();
        return r.table->has(id) ? &r.table->values<T>(id)[r.row] : nullptr;
    }
    template <class T>
    bool has(Entity e) { return get<T>(e) != nullptr; }

    // Calls fn(Entity, Ts&...) for every entity that has all of Ts, table by table.
    template <class... Ts, class Fn>
    void each(Fn&& fn) {
        const std::array<ComponentId, sizeof...(Ts)> ids{component<Ts>()...};
        for (const auto& table : tables_) {
            bool matches = true;
            for (const ComponentId id : ids) matches = matches && table->has(id);
            if (!matches || table->size() == 0) continue;
            eachRow<Ts...>(*table, ids, fn, std::index_sequence_for<Ts...>{});
        }
    }

    // ---- singletons: one object per type, destroyed in reverse order of insertion ----
    template <class T>
    T& set(T value) {
        const std::type_index key(typeid(T));
        if (auto it = singletonIndex_.find(key); it != singletonIndex_.end())
            return *static_cast<T*>(singletons_[it->second].get()) = std::move(value);
        singletonIndex_.emplace(key, singletons_.size());
        singletons_.push_back(std::make_shared<T>(std::move(value)));
        return *static_cast<T*>(singletons_.back().get());
    }
    template <class T>
    T* trySingleton() {
        const auto it = singletonIndex_.find(std::type_index(typeid(T)));
        return it == singletonIndex_.end() ? nullptr : static_cast<T*>(singletons_[it->second].get());
    }
    template <class T>
    T& singleton() {
        if (T* p = trySingleton<T>()) return *p;
        throw std::logic_error(std::string("mini_host ECS: no singleton ") + typeid(T).name());
    }

    // ---- systems, phases, modules ----
    void system(std::string name, Phase phase, std::function<void(World&)> run);
    void runPhase(Phase phase);
    void progress();  // every phase once
    const std::vector<System>& systems() const { return systems_; }

    // Imports a module once: Module::import(World&) registers its components, singletons and systems.
    template <class Module>
    void import() {
        if (imported_.insert(std::type_index(typeid(Module))).second) Module::import(*this);
    }

private:
    struct Record {
        Table* table = nullptr;
        std::size_t row = 0;
    };
    Record& record(Entity e);
    Table& tableOf(const std::vector<ComponentId>& type);
    Table& neighbour(Table& from, ComponentId id, bool adding);
    void moveEntity(Entity e, Table& to);
    void removeRow(Table& table, std::size_t row);

    template <class... Ts, class Fn, std::size_t... I>
    void eachRow(Table& table, const std::array<ComponentId, sizeof...(Ts)>& ids, Fn& fn, std::index_sequence<I...>) {
        auto columns = std::tie(table.values<Ts>(ids[I])...);
        const std::vector<Entity>& entities = table.entities();
        for (std::size_t row = 0; row < entities.size(); ++row) fn(entities[row], std::get<I>(columns)[row]...);
    }

    std::vector<std::unique_ptr<Table>> tables_;
    std::map<std::vector<ComponentId>, Table*> tableByType_;
    std::vector<Record> records_;  // index: entity; records_[0] unused
    std::unordered_map<std::type_index, ComponentId> componentIds_;
    std::vector<std::unique_ptr<Column>> emptyColumns_;  // per component id: the prototype of its columns
    std::vector<std::shared_ptr<void>> singletons_;
    std::unordered_map<std::type_index, std::size_t> singletonIndex_;
    std::vector<System> systems_;
    std::set<std::type_index> imported_;
};

}  // namespace mini::ecs
