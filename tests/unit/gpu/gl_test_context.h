#pragma once
// Test helper: one headless GL context per test suite.
#include <gtest/gtest.h>

#include <memory>

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

}  // namespace nimbus::gpu::test
