#pragma once
// Builds error messages by appending pieces. Not `"literal" + std::string`: GCC 12 at -O3 reports a
// false -Wrestrict on that pattern, which -Werror turns into a build failure.
#include <initializer_list>
#include <string>
#include <string_view>

namespace nimbus::ecs::detail {

inline std::string message(std::initializer_list<std::string_view> parts) {
    std::string out;
    for (std::string_view part : parts) out.append(part);
    return out;
}

// 'name', for names inside messages.
inline std::string quoted(std::string_view name) { return message({"'", name, "'"}); }

}  // namespace nimbus::ecs::detail
