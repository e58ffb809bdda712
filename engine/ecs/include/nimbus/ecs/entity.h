#pragma once
// An entity handle: a slot index plus the generation the slot had when the entity was created.
// Destroying an entity bumps its slot's generation, so an old handle is recognised as stale even
// after the index is handed out again.
#include <cstdint>
#include <functional>
#include <limits>
#include <string>

namespace nimbus::ecs {

struct Entity {
    static constexpr std::uint32_t kNullIndex = std::numeric_limits<std::uint32_t>::max();

    std::uint32_t index = kNullIndex;
    std::uint32_t generation = 0;

    constexpr bool isNull() const { return index == kNullIndex; }
    // Index and generation in one number, for hashing and for tools that store handles.
    constexpr std::uint64_t bits() const { return (std::uint64_t{generation} << 32) | index; }
    static constexpr Entity fromBits(std::uint64_t bits) {
        return Entity{static_cast<std::uint32_t>(bits), static_cast<std::uint32_t>(bits >> 32)};
    }

    friend constexpr bool operator==(Entity, Entity) = default;
};

// The handle no entity ever has; a default-constructed Entity is this.
inline constexpr Entity kNullEntity{};

// "12v3" (index 12, generation 3) or "null"; for error messages and logs.
std::string toString(Entity entity);

}  // namespace nimbus::ecs

template <>
struct std::hash<nimbus::ecs::Entity> {
    std::size_t operator()(nimbus::ecs::Entity e) const noexcept { return std::hash<std::uint64_t>{}(e.bits()); }
};
