#pragma once
// Names and type-erased operations of component types, for tools (the editor, scene export) that
// must handle components without knowing their C++ types. Storage does not need it: a World
// stores any type without registration.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "nimbus/ecs/entity.h"
#include "nimbus/ecs/type_id.h"
#include "nimbus/ecs/world.h"

namespace nimbus::ecs {

struct ComponentInfo {
    std::string name;
    TypeId type = 0;
    std::size_t size = 0;
    std::size_t alignment = 0;
    bool (*has)(const World&, Entity) = nullptr;
    bool (*remove)(World&, Entity) = nullptr;  // false if the entity had none
};

class ComponentRegistry {
public:
    // Returns false if T is already registered under `name` (registering twice is harmless).
    // Throws std::logic_error if T has another name, or `name` belongs to another type.
    template <class T>
    bool add(std::string name) {
        static_assert(std::is_same_v<T, std::remove_cvref_t<T>>, "components are plain value types");
        return add(ComponentInfo{std::move(name), typeId<T>(), sizeof(T), alignof(T),
                                 [](const World& w, Entity e) { return w.has<T>(e); },
                                 [](World& w, Entity e) { return w.remove<T>(e); }});
    }
    bool add(ComponentInfo info);

    const ComponentInfo* find(std::string_view name) const;
    const ComponentInfo* find(TypeId type) const;
    template <class T>
    const ComponentInfo* find() const {
        return find(typeId<T>());
    }
    // In registration order.
    const std::vector<ComponentInfo>& all() const { return infos_; }

private:
    std::vector<ComponentInfo> infos_;
};

}  // namespace nimbus::ecs
