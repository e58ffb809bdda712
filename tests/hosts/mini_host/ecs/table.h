#pragma once
// Archetype storage (in the manner of flecs / Unity DOTS): every entity with exactly the same set of
// component types lives in one Table, one Column per type, row r of every column belonging to the
// entity entities()[r]. Adding or removing a component moves the entity to the neighbouring table.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <unordered_map>
#include <utility>
#include <vector>

namespace mini::ecs {

using Entity = std::uint32_t;       // 0 is never an entity
using ComponentId = std::uint32_t;  // per World, in registration order
inline constexpr Entity kNoEntity = 0;

// The values of one component type for every row of a table; typed below, erased here so a table
// can hold any mix of types.
class Column {
public:
    virtual ~Column() = default;
    virtual std::unique_ptr<Column> emptyLike() const = 0;
    // Appends row `row` of this column to `destination` (a column of the same type).
    virtual void moveRowTo(std::size_t row, Column& destination) = 0;
    // Removes `row` by moving the last row into it (rows are unordered).
    virtual void swapRemove(std::size_t row) = 0;
    virtual std::size_t size() const = 0;
};

template <class T>
class TypedColumn final : public Column {
public:
    std::vector<T> values;

    std::unique_ptr<Column> emptyLike() const override { return std::make_unique<TypedColumn<T>>(); }
    void moveRowTo(std::size_t row, Column& destination) override {
        static_cast<TypedColumn<T>&>(destination).values.push_back(std::move(values[row]));
    }
    void swapRemove(std::size_t row) override {
        if (row + 1 != values.size()) values[row] = std::move(values.back());
        values.pop_back();
    }
    std::size_t size() const override { return values.size(); }
};

class Table {
public:
    // `type` sorted ascending; `columns` parallel to it.
    Table(std::vector<ComponentId> type, std::vector<std::unique_ptr<Column>> columns)
        : type_(std::move(type)), columns_(std::move(columns)) {}

    const std::vector<ComponentId>& type() const { return type_; }
    std::vector<Entity>& entities() { return entities_; }
    std::size_t size() const { return entities_.size(); }

    // Position of `id` in type(), or −1 when the table lacks it.
    int columnIndex(ComponentId id) const {
        const auto it = std::lower_bound(type_.begin(), type_.end(), id);
        return it != type_.end() && *it == id ? static_cast<int>(it - type_.begin()) : -1;
    }
    bool has(ComponentId id) const { return columnIndex(id) >= 0; }
    Column& column(std::size_t index) { return *columns_[index]; }
    template <class T>
    std::vector<T>& values(ComponentId id) {
        return static_cast<TypedColumn<T>&>(*columns_[static_cast<std::size_t>(columnIndex(id))]).values;
    }

    // The table graph (flecs' edges): where an entity goes when one component is added or removed,
    // cached so a structural change after the first is one lookup.
    std::unordered_map<ComponentId, Table*> addEdges;
    std::unordered_map<ComponentId, Table*> removeEdges;

private:
    std::vector<ComponentId> type_;
    std::vector<std::unique_ptr<Column>> columns_;
    std::vector<Entity> entities_;
};

}  // namespace mini::ecs
