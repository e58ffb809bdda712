#include "nimbus/ecs/entity.h"

#include "nimbus/ecs/detail/message.h"

namespace nimbus::ecs {

std::string toString(Entity entity) {
    if (entity.isNull()) return "null";
    return detail::message({std::to_string(entity.index), "v", std::to_string(entity.generation)});
}

}  // namespace nimbus::ecs
