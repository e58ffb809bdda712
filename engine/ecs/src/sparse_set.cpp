#include "nimbus/ecs/sparse_set.h"

#include <algorithm>
#include <stdexcept>

#include "nimbus/ecs/detail/message.h"

namespace nimbus::ecs {

SparseSet::~SparseSet() = default;

std::uint32_t SparseSet::sparseAt(std::uint32_t index) const {
    const std::size_t page = index >> kPageBits;
    if (page >= pages_.size() || !pages_[page]) return kAbsent;
    return pages_[page][index & (kPageSize - 1)];
}

std::uint32_t& SparseSet::sparseSlot(std::uint32_t index) {
    const std::size_t page = index >> kPageBits;
    if (page >= pages_.size()) pages_.resize(page + 1);
    if (!pages_[page]) {
        pages_[page] = std::make_unique_for_overwrite<std::uint32_t[]>(kPageSize);
        std::fill_n(pages_[page].get(), kPageSize, kAbsent);
    }
    return pages_[page][index & (kPageSize - 1)];
}

bool SparseSet::contains(Entity entity) const {
    if (entity.isNull()) return false;
    const std::uint32_t pos = sparseAt(entity.index);
    return pos != kAbsent && dense_[pos] == entity;
}

bool SparseSet::insert(Entity entity) {
    if (entity.isNull()) throw std::logic_error("SparseSet::insert: the null entity cannot be a member");
    if (sparseAt(entity.index) != kAbsent) {
        if (contains(entity)) return false;
        // Same index, other generation: the caller kept a stale member. World never does this.
        throw std::logic_error(detail::message({"SparseSet::insert: entity ", toString(entity), " collides with member ",
                                                toString(dense_[sparseAt(entity.index)])}));
    }
    pushDefaultPayload();
    try {
        pushEntity(entity);
    } catch (...) {
        swapAndPopPayload(dense_.size(), dense_.size());  // drop the payload element just added
        throw;
    }
    return true;
}

void SparseSet::pushEntity(Entity entity) {
    std::uint32_t& slot = sparseSlot(entity.index);  // may allocate: do it before growing dense_
    dense_.push_back(entity);
    slot = static_cast<std::uint32_t>(dense_.size() - 1);
}

bool SparseSet::remove(Entity entity) {
    if (!contains(entity)) return false;
    const std::size_t pos = sparseAt(entity.index);
    const std::size_t last = dense_.size() - 1;
    swapAndPopPayload(pos, last);
    const Entity moved = dense_[last];
    dense_[pos] = moved;
    sparseSlot(moved.index) = static_cast<std::uint32_t>(pos);
    sparseSlot(entity.index) = kAbsent;  // after the line above: when pos == last, moved == entity
    dense_.pop_back();
    return true;
}

void SparseSet::clear() {
    clearPayload();
    for (Entity e : dense_) sparseSlot(e.index) = kAbsent;
    dense_.clear();
}

void SparseSet::pushDefaultPayload() {}
void SparseSet::swapAndPopPayload(std::size_t, std::size_t) {}
void SparseSet::clearPayload() {}

}  // namespace nimbus::ecs
