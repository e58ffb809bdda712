#pragma once
// A sparse set of entities: a paged sparse array maps an entity index to a position in a dense
// array of entities. contains/insert/remove are O(1); removal swaps the last entity into the hole
// ("swap and pop"), so the dense array stays packed and iteration touches only members.
// Derived storages (ComponentStorage<T>) keep a component array parallel to the dense array and
// are told, through swapAndPopPayload, to move their last element the same way.
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <span>
#include <vector>

#include "nimbus/ecs/entity.h"

namespace nimbus::ecs {

class SparseSet {
public:
    SparseSet() = default;
    SparseSet(const SparseSet&) = delete;
    SparseSet& operator=(const SparseSet&) = delete;
    SparseSet(SparseSet&&) noexcept = default;
    SparseSet& operator=(SparseSet&&) noexcept = default;
    virtual ~SparseSet();

    // True only for this exact handle: a stale handle whose index is now someone else's is not contained.
    bool contains(Entity entity) const;
    // Position of `entity` in the dense array. Precondition: contains(entity).
    std::size_t position(Entity entity) const { return sparseAt(entity.index); }

    std::size_t size() const { return dense_.size(); }
    bool empty() const { return dense_.empty(); }
    Entity at(std::size_t position) const { return dense_[position]; }
    // The members in dense order. Invalidated by any insert or remove.
    std::span<const Entity> entities() const { return dense_; }

    // Adds `entity` (a storage gives it a default-constructed component). Returns false if already present.
    bool insert(Entity entity);
    // Removes `entity` and its payload; returns false if it was not present. The entity that was
    // last in the dense array takes the freed position.
    bool remove(Entity entity);
    void clear();

protected:
    // Appends `entity` to the dense array; the payload must already hold its element at size().
    void pushEntity(Entity entity);
    // Append a default element to the payload for insert(); called before pushEntity.
    virtual void pushDefaultPayload();
    // Move the payload element at `last` into `position` (unless equal) and drop the last one.
    virtual void swapAndPopPayload(std::size_t position, std::size_t last);
    virtual void clearPayload();

private:
    static constexpr std::uint32_t kAbsent = std::numeric_limits<std::uint32_t>::max();
    static constexpr std::size_t kPageBits = 12;  // 4096 entries (16 KiB) per sparse page
    static constexpr std::size_t kPageSize = std::size_t{1} << kPageBits;

    std::uint32_t sparseAt(std::uint32_t index) const;
    std::uint32_t& sparseSlot(std::uint32_t index);  // allocates the page on demand

    std::vector<std::unique_ptr<std::uint32_t[]>> pages_;  // entity index -> dense position or kAbsent
    std::vector<Entity> dense_;
};

}  // namespace nimbus::ecs
