#include "nimbus/ecs/component_registry.h"

#include <algorithm>
#include <stdexcept>

#include "nimbus/ecs/detail/message.h"

namespace nimbus::ecs {

bool ComponentRegistry::add(ComponentInfo info) {
    if (info.name.empty()) throw std::logic_error("ComponentRegistry::add: a component needs a name");
    if (const ComponentInfo* byType = find(info.type)) {
        if (byType->name == info.name) return false;
        throw std::logic_error(detail::message({"ComponentRegistry::add: one type registered as both ",
                                                detail::quoted(byType->name), " and ", detail::quoted(info.name)}));
    }
    if (find(info.name))
        throw std::logic_error(detail::message({"ComponentRegistry::add: the name ", detail::quoted(info.name),
                                                " already names another component type"}));
    infos_.push_back(std::move(info));
    return true;
}

const ComponentInfo* ComponentRegistry::find(std::string_view name) const {
    auto it = std::find_if(infos_.begin(), infos_.end(), [&](const ComponentInfo& c) { return c.name == name; });
    return it == infos_.end() ? nullptr : &*it;
}

const ComponentInfo* ComponentRegistry::find(TypeId type) const {
    auto it = std::find_if(infos_.begin(), infos_.end(), [&](const ComponentInfo& c) { return c.type == type; });
    return it == infos_.end() ? nullptr : &*it;
}

}  // namespace nimbus::ecs
