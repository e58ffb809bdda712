#include "nimbus/base/error.h"

namespace nimbus {

std::string describeInputProblem(std::string_view file, std::string_view object, std::string_view field,
                                 std::string_view problem) {
    std::string out;
    for (std::string_view part : {file, object, field}) {
        if (part.empty()) continue;
        out.append(part);
        out.append(": ");
    }
    out.append(problem);
    // One line, always: a reason printed by the sandbox must not spill over several lines.
    for (char& c : out)
        if (c == '\n' || c == '\r') c = ' ';
    return out;
}

std::string typedText(std::string_view text) {
    constexpr std::size_t kShown = 24;
    if (text.size() <= kShown) return std::string(text);
    return std::string(text.substr(0, kShown)) + "... (" + std::to_string(text.size()) + " characters)";
}

void throwInputError(std::string_view file, std::string_view object, std::string_view field,
                     std::string_view problem) {
    throw InputError(describeInputProblem(file, object, field, problem));
}

}  // namespace nimbus
