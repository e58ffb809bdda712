#include "nimbus/ecs/world.h"

#include "nimbus/ecs/detail/message.h"

namespace nimbus::ecs {
namespace {

// "World::get<Velocity>"
std::string describe(std::string_view operation, std::string_view type) {
    if (type.empty()) return detail::message({"World::", operation});
    return detail::message({"World::", operation, "<", type, ">"});
}

}  // namespace

World::World() = default;
World::World(World&&) noexcept = default;

World& World::operator=(World&& other) noexcept {
    if (this != &other) {
        pools_.clear();  // components before resources, as in the destructor
        resources_ = std::move(other.resources_);
        pools_ = std::move(other.pools_);
        slots_ = std::move(other.slots_);
        free_ = std::move(other.free_);
        aliveCount_ = std::exchange(other.aliveCount_, 0);
    }
    return *this;
}

World::~World() {
    // Components may hold things a resource provides (GL objects and the GL context): drop them first.
    pools_.clear();
    resources_.clear();
}

Entity World::create() {
    std::uint32_t index;
    if (!free_.empty()) {
        index = free_.back();
        free_.pop_back();
    } else {
        if (slots_.size() >= Entity::kNullIndex) throw std::length_error("World::create: out of entity indices");
        index = static_cast<std::uint32_t>(slots_.size());
        slots_.emplace_back();
    }
    slots_[index].alive = true;
    ++aliveCount_;
    return Entity{index, slots_[index].generation};
}

bool World::alive(Entity entity) const {
    return entity.index < slots_.size() && slots_[entity.index].alive &&
           slots_[entity.index].generation == entity.generation;
}

void World::destroy(Entity entity) {
    requireAlive(entity, "destroy", {});
    for (auto& pool : pools_)
        if (pool) pool->remove(entity);
    Slot& slot = slots_[entity.index];
    slot.alive = false;
    --aliveCount_;
    // A slot whose generation would wrap is retired rather than reused: a wrapped generation could
    // make a very old handle look alive again.
    if (slot.generation == std::numeric_limits<std::uint32_t>::max()) return;
    ++slot.generation;
    free_.push_back(entity.index);
}

void World::clear() {
    for (auto& pool : pools_)
        if (pool) pool->clear();
    free_.clear();
    for (std::uint32_t i = static_cast<std::uint32_t>(slots_.size()); i-- > 0;) {
        Slot& slot = slots_[i];
        if (slot.alive) {
            slot.alive = false;
            if (slot.generation == std::numeric_limits<std::uint32_t>::max()) continue;
            ++slot.generation;
        } else if (slot.generation == std::numeric_limits<std::uint32_t>::max()) {
            continue;  // retired
        }
        free_.push_back(i);  // pushed high to low, so create() hands out low indices first
    }
    aliveCount_ = 0;
}

void World::requireAlive(Entity entity, std::string_view operation, std::string_view type) const {
    if (alive(entity)) return;
    std::string text = describe(operation, type);
    if (entity.isNull())
        text.append(": the null entity");
    else
        text.append(": entity ").append(toString(entity)).append(" is not alive (destroyed, or from another world)");
    throw std::logic_error(text);
}

void World::throwMissingComponent(std::string_view operation, std::string_view type, Entity entity) const {
    requireAlive(entity, operation, type);
    throwComponentProblem(operation, type, entity, "has none");
}

void World::throwComponentProblem(std::string_view operation, std::string_view type, Entity entity,
                                  std::string_view problem) {
    std::string text = describe(operation, type);
    text.append(": entity ").append(toString(entity)).append(" ").append(problem);
    throw std::logic_error(text);
}

}  // namespace nimbus::ecs
