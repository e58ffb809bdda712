#pragma once
// Test helper: run `f`, expect a std::logic_error whose message contains `needle`.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <string_view>

namespace nimbus::ecs::test {

template <class F>
::testing::AssertionResult throwsLogicError(F&& f, std::string_view needle) {
    try {
        f();
    } catch (const std::logic_error& error) {
        if (std::string(error.what()).find(needle) != std::string::npos) return ::testing::AssertionSuccess();
        return ::testing::AssertionFailure() << "message lacks \"" << needle << "\": " << error.what();
    }
    return ::testing::AssertionFailure() << "no std::logic_error thrown";
}

}  // namespace nimbus::ecs::test
