#pragma once
// A view over the entities that have every component in C...: it walks the smallest of the pools
// and checks the others. `const C` in the list gives read-only access to that component.
//
//   world.view<Position, const Velocity>().each([](Entity e, Position& p, const Velocity& v) { ... });
//   for (auto [e, p, v] : world.view<Position, const Velocity>()) { ... }
//
// Iteration runs backwards over the driving pool's dense array (as EnTT does), which makes these
// safe inside the loop body:
//   - removing components from, or destroying, the entity being visited;
//   - creating entities and emplacing components on any entity (components never move on growth,
//     so references handed to the body stay valid; an entity that gains the last missing component
//     during the loop may or may not be visited);
//   - reading or writing any component of any entity.
// Not safe: removing components from, or destroying, an entity other than the current one; that
// may visit an entity twice or skip one (memory stays valid, the set visited does not).
// A view holds pointers to pools, not a snapshot: make one per system run, it costs nothing.
#include <algorithm>
#include <cstddef>
#include <iterator>
#include <tuple>
#include <type_traits>

#include "nimbus/ecs/component_storage.h"
#include "nimbus/ecs/entity.h"

namespace nimbus::ecs {

// The storage a view element refers to: const storage for a const component.
template <class C>
using StorageFor = std::conditional_t<std::is_const_v<C>, const ComponentStorage<std::remove_const_t<C>>,
                                      ComponentStorage<std::remove_const_t<C>>>;

template <class... C>
class View {
    static_assert(sizeof...(C) > 0, "a view needs at least one component type");

public:
    using Element = std::tuple<Entity, C&...>;

    class Iterator {
    public:
        using iterator_category = std::forward_iterator_tag;
        using value_type = Element;
        using difference_type = std::ptrdiff_t;
        using pointer = void;
        using reference = Element;

        Iterator() = default;
        Element operator*() const { return view_->element(lead_->at(next_ - 1)); }
        Iterator& operator++() {
            next_ = std::min(next_ - 1, lead_->size());  // the body may have shrunk the pool
            skipNonMembers();
            return *this;
        }
        Iterator operator++(int) {
            Iterator old = *this;
            ++*this;
            return old;
        }
        friend bool operator==(const Iterator& a, const Iterator& b) { return a.next_ == b.next_; }

    private:
        friend class View;
        Iterator(const View* view, const SparseSet* lead, std::size_t next) : view_(view), lead_(lead), next_(next) {
            skipNonMembers();
        }
        void skipNonMembers() {
            while (next_ > 0 && !view_->contains(lead_->at(next_ - 1))) --next_;
        }

        const View* view_ = nullptr;
        const SparseSet* lead_ = nullptr;
        std::size_t next_ = 0;  // dense position of the current entity + 1; 0 is the end
    };

    View() = default;  // empty
    explicit View(StorageFor<C>*... storages) : storages_(storages...) {}

    // True when `entity` has every component of the view.
    bool contains(Entity entity) const {
        return std::apply([&](auto*... s) { return ((s != nullptr && s->contains(entity)) && ...); }, storages_);
    }

    // One component of an entity in the view. Precondition: contains(entity).
    template <class T>
    decltype(auto) get(Entity entity) const {
        return std::get<StorageFor<T>*>(storages_)->get(entity);
    }

    // An upper bound of the number of entities visited: the size of the smallest pool.
    std::size_t sizeHint() const {
        const SparseSet* lead = leadPool();
        return lead ? lead->size() : 0;
    }

    // Calls f(Entity, C&...) or f(C&...) for every entity with all components.
    template <class F>
    void each(F&& f) const {
        const SparseSet* lead = leadPool();
        if (!lead) return;
        for (std::size_t next = lead->size(); next > 0; next = std::min(next - 1, lead->size())) {
            const Entity entity = lead->at(next - 1);
            if (!contains(entity)) continue;
            if constexpr (std::is_invocable_v<F&, Entity, C&...>)
                f(entity, std::get<StorageFor<C>*>(storages_)->get(entity)...);
            else
                f(std::get<StorageFor<C>*>(storages_)->get(entity)...);
        }
    }

    Iterator begin() const {
        const SparseSet* lead = leadPool();
        return lead ? Iterator(this, lead, lead->size()) : Iterator();
    }
    Iterator end() const { return Iterator(); }

private:
    Element element(Entity entity) const { return Element(entity, std::get<StorageFor<C>*>(storages_)->get(entity)...); }

    // The smallest pool, or null when some pool does not exist (then nothing has all components).
    const SparseSet* leadPool() const {
        const SparseSet* lead = nullptr;
        bool missing = false;
        std::apply(
            [&](auto*... s) {
                ((s == nullptr ? void(missing = true)
                               : void(lead = (lead == nullptr || s->size() < lead->size()) ? s : lead)),
                 ...);
            },
            storages_);
        return missing ? nullptr : lead;
    }

    std::tuple<StorageFor<C>*...> storages_{};
};

}  // namespace nimbus::ecs
