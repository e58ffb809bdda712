#pragma once
// Small dense ids for C++ types, made by a template instead of RTTI or registration macros.
// Ids are handed out on first use, so they differ between runs: never store them, store names.
#include <atomic>
#include <cstdint>
#include <string_view>
#include <type_traits>

namespace nimbus::ecs {

using TypeId = std::uint32_t;

namespace detail {
inline TypeId nextTypeId() {
    // The one piece of process-wide mutable state: a counter. Atomic, since worlds may be built
    // on several threads (tests, the reference renderer's workers).
    static std::atomic<TypeId> next{0};
    return next.fetch_add(1, std::memory_order_relaxed);
}

template <class T>
TypeId typeIdOfDecayed() {
    static const TypeId id = nextTypeId();
    return id;
}
}  // namespace detail

// The same id for T, const T and T& alike.
template <class T>
TypeId typeId() {
    return detail::typeIdOfDecayed<std::remove_cvref_t<T>>();
}

// A readable name of T for error messages ("Velocity", "nimbus::media::Emitter"); compiler-made,
// so only for people to read.
template <class T>
constexpr std::string_view typeName() {
    std::string_view s = __PRETTY_FUNCTION__;  // GCC/Clang: "... typeName() [with T = Foo; ...]" / "[T = Foo]"
    const std::size_t start = s.find("T = ");
    if (start == std::string_view::npos) return s;
    s.remove_prefix(start + 4);
    const std::size_t end = s.find_first_of(";]");
    return end == std::string_view::npos ? s : s.substr(0, end);
}

}  // namespace nimbus::ecs
