// GL error reporting (gpu/debug.h through Context::takeGlErrors): a deliberately provoked error is
// reported once, with or without KHR_debug, and the report resets.
#include "nimbus/gpu/debug.h"

#include <gtest/gtest.h>

#include <epoxy/gl.h>

#include "nimbus/gpu/context.h"

namespace nimbus::gpu {
namespace {

void provokeInvalidEnum() { glEnable(0xDEAD); }  // not a capability: GL_INVALID_ENUM

TEST(TakeGlErrors, ReportsAProvokedErrorThroughGlGetError) {
    auto context = Context::create({.debug = ContextDesc::Debug::Off});
    EXPECT_FALSE(context->debugEnabled());
    EXPECT_EQ(context->takeGlErrors().count, 0u);
    provokeInvalidEnum();
    const GlErrorReport report = context->takeGlErrors();
    EXPECT_EQ(report.count, 1u);
    EXPECT_EQ(report.first, "glGetError 0x0500");  // GL_INVALID_ENUM
    const GlErrorReport again = context->takeGlErrors();
    EXPECT_EQ(again.count, 0u) << "take() resets";
    EXPECT_TRUE(again.first.empty());
}

TEST(TakeGlErrors, ReportsAProvokedErrorThroughKhrDebug) {
    auto context = Context::create({.debug = ContextDesc::Debug::On});
    EXPECT_TRUE(context->debugEnabled());
    EXPECT_EQ(context->takeGlErrors().count, 0u);
    provokeInvalidEnum();
    const GlErrorReport report = context->takeGlErrors();
    // The debug callback sees it (synchronously) and glGetError still holds the code: at least one.
    EXPECT_GE(report.count, 1u);
    EXPECT_EQ(report.first.rfind("GL ", 0), 0u) << "the first report is the driver's KHR_debug message: " << report.first;
    EXPECT_EQ(context->takeGlErrors().count, 0u);
}

TEST(TakeGlErrors, EachReportHoldsOnlyErrorsSinceTheLastOne) {
    auto context = Context::create({.debug = ContextDesc::Debug::Off});
    provokeInvalidEnum();
    EXPECT_EQ(context->takeGlErrors().first, "glGetError 0x0500");
    glViewport(0, 0, -1, -1);  // GL_INVALID_VALUE
    // (Mesa keeps one glGetError flag at a time, so two errors before a take may count as one.)
    const GlErrorReport report = context->takeGlErrors();
    EXPECT_EQ(report.count, 1u);
    EXPECT_EQ(report.first, "glGetError 0x0501");
}

TEST(GlErrorLog, RecordsKeepTheFirstMessage) {
    GlErrorLog log;
    log.record("first");
    log.record("second");
    // take() also drains glGetError, which needs a context.
    auto context = Context::create({.debug = ContextDesc::Debug::Off});
    const GlErrorReport report = log.take();
    EXPECT_EQ(report.count, 2u);
    EXPECT_EQ(report.first, "first");
}

}  // namespace
}  // namespace nimbus::gpu
