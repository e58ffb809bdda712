#include "ecs/world.h"

#include <algorithm>
#include <string>

namespace mini::ecs {

const char* phaseName(Phase phase) {
    switch (phase) {
        case Phase::OnLoad: return "OnLoad";
        case Phase::PostLoad: return "PostLoad";
        case Phase::OnUpdate: return "OnUpdate";
        case Phase::PreStore: return "PreStore";
        case Phase::OnStore: return "OnStore";
    }
    return "?";
}

World::World() {
    records_.emplace_back();  // entity 0 stays invalid
    tableOf({});              // the root table: entities without components
}

World::~World() {
    // Later singletons may hold on to earlier ones (GL objects on a context): drop newest first.
    while (!singletons_.empty()) singletons_.pop_back();
}

Entity World::entity() {
    const auto e = static_cast<Entity>(records_.size());
    Table& root = tableOf({});
    root.entities().push_back(e);
    records_.push_back({&root, root.size() - 1});
    return e;
}

void World::destroy(Entity e) {
    Record& r = record(e);
    removeRow(*r.table, r.row);
    r.table = nullptr;  // ids are not reused: a stale handle stays dead
}

World::Record& World::record(Entity e) {
    if (!alive(e)) throw std::logic_error("mini_host ECS: entity " + std::to_string(e) + " does not exist");
    return records_[e];
}

Table& World::tableOf(const std::vector<ComponentId>& type) {
    if (const auto it = tableByType_.find(type); it != tableByType_.end()) return *it->second;
    std::vector<std::unique_ptr<Column>> columns;
    for (const ComponentId id : type) columns.push_back(emptyColumns_[id]->emptyLike());
    tables_.push_back(std::make_unique<Table>(type, std::move(columns)));
    tableByType_.emplace(type, tables_.back().get());
    return *tables_.back();
}

// The table whose type is `from`'s plus (or minus) `id`, through the cached edge when there is one.
Table& World::neighbour(Table& from, ComponentId id, bool adding) {
    auto& edges = adding ? from.addEdges : from.removeEdges;
    if (const auto it = edges.find(id); it != edges.end()) return *it->second;
    std::vector<ComponentId> type = from.type();
    if (adding) type.insert(std::lower_bound(type.begin(), type.end(), id), id);
    else type.erase(std::find(type.begin(), type.end(), id));
    Table& to = tableOf(type);  // may grow tables_, never moves a Table (they are heap objects)
    edges.emplace(id, &to);
    return to;
}

// Moves e's row to `to`: every component both tables have is moved over; a component only `from`
// has is dropped; one only `to` has must be appended by the caller right after.
void World::moveEntity(Entity e, Table& to) {
    Record& r = record(e);
    Table& from = *r.table;
    for (std::size_t c = 0; c < from.type().size(); ++c) {
        const int target = to.columnIndex(from.type()[c]);
        if (target >= 0) from.column(c).moveRowTo(r.row, to.column(static_cast<std::size_t>(target)));
    }
    const std::size_t oldRow = r.row;
    to.entities().push_back(e);
    r = {&to, to.size() - 1};
    removeRow(from, oldRow);
}

void World::removeRow(Table& table, std::size_t row) {
    for (std::size_t c = 0; c < table.type().size(); ++c) table.column(c).swapRemove(row);
    std::vector<Entity>& entities = table.entities();
    const Entity last = entities.back();
    entities[row] = last;
    entities.pop_back();
    if (row < entities.size()) records_[last].row = row;  // the last row now lives at `row`
}

void World::system(std::string name, Phase phase, std::function<void(World&)> run) {
    systems_.push_back({std::move(name), phase, std::move(run)});
}

void World::runPhase(Phase phase) {
    // By index: a system may register another (it runs from the next pass over this phase on).
    const std::size_t count = systems_.size();
    for (std::size_t i = 0; i < count; ++i)
        if (systems_[i].phase == phase) systems_[i].run(*this);
}

void World::progress() {
    for (const Phase phase : kPhases) runPhase(phase);
}

}  // namespace mini::ecs
