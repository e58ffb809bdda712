#pragma once
// Storage of one component type: a SparseSet of entities plus a component array parallel to its
// dense array (component i belongs to entities()[i]). Components live in a PagedVector, so adding
// components never moves existing ones; removing one moves the last component into its place.
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

#include "nimbus/ecs/detail/message.h"
#include "nimbus/ecs/paged_vector.h"
#include "nimbus/ecs/sparse_set.h"
#include "nimbus/ecs/type_id.h"

namespace nimbus::ecs {

template <class T>
class ComponentStorage final : public SparseSet {
    static_assert(std::is_same_v<T, std::remove_cvref_t<T>>, "components are plain value types");
    static_assert(std::is_move_constructible_v<T> && std::is_move_assignable_v<T>,
                  "swap-and-pop removal moves components: they must be move-constructible and move-assignable");

public:
    // Precondition: !contains(entity) and entity is not null.
    template <class... Args>
    T& emplace(Entity entity, Args&&... args) {
        T& value = components_.emplace_back(std::forward<Args>(args)...);
        try {
            pushEntity(entity);
        } catch (...) {
            components_.pop_back();
            throw;
        }
        return value;
    }

    // Precondition: contains(entity).
    T& get(Entity entity) { return components_[position(entity)]; }
    const T& get(Entity entity) const { return components_[position(entity)]; }

    T* tryGet(Entity entity) { return contains(entity) ? &components_[position(entity)] : nullptr; }
    const T* tryGet(Entity entity) const { return contains(entity) ? &components_[position(entity)] : nullptr; }

    // The component at a dense position (parallel to entities()).
    T& atPosition(std::size_t pos) { return components_[pos]; }
    const T& atPosition(std::size_t pos) const { return components_[pos]; }

private:
    void pushDefaultPayload() override {
        if constexpr (std::is_default_constructible_v<T>)
            components_.emplace_back();
        else
            throw std::logic_error(detail::message(
                {"ComponentStorage::insert: ", typeName<T>(), " is not default-constructible; use emplace"}));
    }
    void swapAndPopPayload(std::size_t pos, std::size_t last) override {
        if (pos != last) components_[pos] = std::move(components_[last]);
        components_.pop_back();
    }
    void clearPayload() override { components_.clear(); }

    PagedVector<T> components_;
};

}  // namespace nimbus::ecs
