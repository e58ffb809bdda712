#pragma once
// The World (EnTT's "registry"): entities, one sparse-set storage per component type, and the typed
// resources. Operations on a dead or stale handle that would change it throw std::logic_error
// (programmer errors); queries (alive, has, tryGet) just answer false or null.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "nimbus/ecs/component_storage.h"
#include "nimbus/ecs/entity.h"
#include "nimbus/ecs/resources.h"
#include "nimbus/ecs/type_id.h"
#include "nimbus/ecs/view.h"

namespace nimbus::ecs {

class World {
public:
    World();
    World(const World&) = delete;
    World& operator=(const World&) = delete;
    World(World&&) noexcept;
    World& operator=(World&&) noexcept;
    ~World();

    // ---- entities ----
    Entity create();
    // Removes all of the entity's components, then frees its index (with a new generation).
    void destroy(Entity entity);
    bool alive(Entity entity) const;
    std::size_t size() const { return aliveCount_; }  // live entities
    // Destroys every entity and component; resources stay. Old handles all become stale.
    void clear();
    // Calls f(Entity) for every live entity, in index order.
    template <class F>
    void forEachEntity(F&& f) const {
        for (std::uint32_t i = 0; i < slots_.size(); ++i)
            if (slots_[i].alive) f(Entity{i, slots_[i].generation});
    }

    // ---- components ----
    // Adds a T made from args; throws if the entity already has one.
    template <class T, class... Args>
    T& emplace(Entity entity, Args&&... args) {
        requireAlive(entity, "emplace", typeName<T>());
        ComponentStorage<T>& s = storage<T>();
        if (s.contains(entity)) throwComponentProblem("emplace", typeName<T>(), entity, "already has one");
        return s.emplace(entity, std::forward<Args>(args)...);
    }
    // Overwrites the entity's T with one made from args; throws if it has none.
    template <class T, class... Args>
    T& replace(Entity entity, Args&&... args) {
        T& current = get<T>(entity);
        current = makeValue<T>(std::forward<Args>(args)...);
        return current;
    }
    template <class T, class... Args>
    T& emplaceOrReplace(Entity entity, Args&&... args) {
        if (T* current = tryGet<T>(entity)) {
            *current = makeValue<T>(std::forward<Args>(args)...);
            return *current;
        }
        return emplace<T>(entity, std::forward<Args>(args)...);
    }
    // Removes the entity's T; returns false if it had none. Throws for a dead handle.
    template <class T>
    bool remove(Entity entity) {
        requireAlive(entity, "remove", typeName<T>());
        ComponentStorage<T>* s = findStorage<T>();
        return s != nullptr && s->remove(entity);
    }

    // The entity's T; throws std::logic_error when it has none (or the handle is stale).
    template <class T>
    T& get(Entity entity) {
        if (T* p = tryGet<T>(entity)) return *p;
        throwMissingComponent("get", typeName<T>(), entity);
    }
    template <class T>
    const T& get(Entity entity) const {
        if (const T* p = tryGet<T>(entity)) return *p;
        throwMissingComponent("get", typeName<T>(), entity);
    }
    template <class T>
    T* tryGet(Entity entity) {
        ComponentStorage<T>* s = findStorage<T>();
        return s ? s->tryGet(entity) : nullptr;
    }
    template <class T>
    const T* tryGet(Entity entity) const {
        const ComponentStorage<T>* s = findStorage<T>();
        return s ? s->tryGet(entity) : nullptr;
    }
    // True when the entity is alive and has every one of T...
    template <class... T>
    bool has(Entity entity) const {
        return ((tryGet<T>(entity) != nullptr) && ...);
    }
    // Number of entities with a T.
    template <class T>
    std::size_t count() const {
        const ComponentStorage<T>* s = findStorage<T>();
        return s ? s->size() : 0;
    }

    // ---- views (see view.h for what is safe while iterating) ----
    template <class... C>
    View<C...> view() {
        return View<C...>(&storageFor<C>()...);
    }
    template <class... C>
    View<const C...> view() const {
        return View<const C...>(findStorage<std::remove_const_t<C>>()...);
    }

    // ---- resources (one value per type; see resources.h) ----
    template <class T, class... Args>
    T& insertResource(Args&&... args) {
        return resources_.insert<T>(std::forward<Args>(args)...);
    }
    template <class T>
    T& resource() {
        return resources_.get<T>();
    }
    template <class T>
    const T& resource() const {
        return resources_.get<T>();
    }
    template <class T>
    T* tryResource() {
        return resources_.tryGet<T>();
    }
    template <class T>
    const T* tryResource() const {
        return resources_.tryGet<T>();
    }
    template <class T>
    bool hasResource() const {
        return resources_.contains<T>();
    }
    template <class T>
    bool removeResource() {
        return resources_.remove<T>();
    }
    Resources& resources() { return resources_; }
    const Resources& resources() const { return resources_; }

private:
    struct Slot {
        std::uint32_t generation = 0;
        bool alive = false;
    };

    template <class T, class... Args>
    static T makeValue(Args&&... args) {
        if constexpr (std::is_constructible_v<T, Args&&...>)
            return T(std::forward<Args>(args)...);
        else
            return T{std::forward<Args>(args)...};
    }

    template <class T>
    ComponentStorage<T>& storage() {
        const TypeId id = typeId<T>();
        if (id >= pools_.size()) pools_.resize(id + 1);
        if (!pools_[id]) pools_[id] = std::make_unique<ComponentStorage<T>>();
        return static_cast<ComponentStorage<T>&>(*pools_[id]);
    }
    template <class C>
    StorageFor<C>& storageFor() {
        return storage<std::remove_const_t<C>>();
    }
    template <class T>
    ComponentStorage<T>* findStorage() const {
        const TypeId id = typeId<T>();
        return id < pools_.size() ? static_cast<ComponentStorage<T>*>(pools_[id].get()) : nullptr;
    }

    void requireAlive(Entity entity, std::string_view operation, std::string_view type) const;
    [[noreturn]] void throwMissingComponent(std::string_view operation, std::string_view type, Entity entity) const;
    [[noreturn]] static void throwComponentProblem(std::string_view operation, std::string_view type, Entity entity,
                                                   std::string_view problem);

    std::vector<Slot> slots_;           // by entity index
    std::vector<std::uint32_t> free_;   // dead indices to reuse, most recently freed last
    std::size_t aliveCount_ = 0;
    Resources resources_;               // declared before pools_: components go first on destruction
    std::vector<std::unique_ptr<SparseSet>> pools_;  // by component TypeId; null where unused
};

}  // namespace nimbus::ecs
