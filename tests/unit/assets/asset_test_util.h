#pragma once
// Helpers shared by the asset tests: where test data lives, and loading that must fail.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "nimbus/assets/scene.h"
#include "nimbus/base/error.h"

namespace nimbus::assets::test {

inline std::filesystem::path dataPath(const std::string& relative) {
    return std::filesystem::path(NIMBUS_TEST_DATA_DIR) / relative;
}

// Loads `file` expecting an InputError; returns its message ("" and a test failure when it loads).
inline std::string refusalOf(const std::filesystem::path& file) {
    try {
        loadScene(file);
    } catch (const InputError& e) {
        return e.what();
    } catch (const std::exception& e) {
        ADD_FAILURE() << file << " threw something other than InputError: " << e.what();
        return {};
    }
    ADD_FAILURE() << file << " loaded but should have been refused";
    return {};
}

inline bool isOneLine(const std::string& s) { return s.find('\n') == std::string::npos && s.find('\r') == std::string::npos; }

}  // namespace nimbus::assets::test
