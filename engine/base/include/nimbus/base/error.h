#pragma once
// Errors that reach a user. Bad input is refused with one message naming the file, the object and
// the field; the sandbox prints it on one line and exits non-zero.
#include <stdexcept>
#include <string>
#include <string_view>

namespace nimbus {

// Thrown for input the user can fix: a malformed scene, an out-of-range value, a bad argument.
class InputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Thrown when the machine cannot do what was asked (no GL 4.5 context, a shader that fails to compile).
class SystemError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// "file: object: field: problem" with empty parts left out.
std::string describeInputProblem(std::string_view file, std::string_view object, std::string_view field,
                                 std::string_view problem);

// What a user typed, for a message: as typed, or its start and its length when it is long (a
// 300-digit number is not repeated back).
std::string typedText(std::string_view text);

[[noreturn]] void throwInputError(std::string_view file, std::string_view object, std::string_view field,
                                  std::string_view problem);

}  // namespace nimbus
