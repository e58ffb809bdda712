#pragma once
// Test helpers: one headless GL context per test suite, and a scratch folder of shader files.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include <unistd.h>

#include "nimbus/gpu/context.h"

namespace nimbus::gpu::test {

// A suite whose tests share one current context (made once: creating one costs tens of ms).
class GlTest : public ::testing::Test {
protected:
    static void SetUpTestSuite() { context_ = Context::create({.debug = ContextDesc::Debug::Off}); }
    static void TearDownTestSuite() { context_.reset(); }
    void SetUp() override {
        context_->makeCurrent();
        (void)context_->takeGlErrors();  // start each test clean
    }
    static Context& context() { return *context_; }

private:
    static inline std::unique_ptr<Context> context_;
};

// A fresh folder under the system temp dir, removed at the end of the test.
class ScratchFolder {
public:
    ScratchFolder() {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        path_ = std::filesystem::temp_directory_path() /
                ("nimbus_gpu_" + std::to_string(::getpid()) + "_" + (info ? std::string(info->name()) : "suite"));
        std::filesystem::remove_all(path_);
        std::filesystem::create_directories(path_);
    }
    ~ScratchFolder() {
        std::error_code ignored;
        std::filesystem::remove_all(path_, ignored);
    }
    ScratchFolder(const ScratchFolder&) = delete;
    ScratchFolder& operator=(const ScratchFolder&) = delete;

    const std::filesystem::path& path() const { return path_; }
    void write(const std::string& name, const std::string& text) const {
        std::filesystem::create_directories((path_ / name).parent_path());
        std::ofstream(path_ / name, std::ios::binary) << text;
    }

private:
    std::filesystem::path path_;
};

}  // namespace nimbus::gpu::test
