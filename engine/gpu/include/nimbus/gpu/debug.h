#pragma once
// GL error reporting. With KHR_debug enabled, driver messages go to the log and errors are counted,
// so tests can assert "no GL error" after a frame. glGetError is drained too, in every build.
#include <cstdint>
#include <mutex>
#include <string>

namespace nimbus::gpu {

struct GlErrorReport {
    std::uint64_t count = 0;
    std::string first;  // the first message, for a test failure
};

// Owned by the Context; the KHR_debug callback writes into it through its user pointer.
class GlErrorLog {
public:
    // Installs the KHR_debug callback on the current context (synchronous output).
    void installDebugOutput();
    // Errors seen since the last call (KHR_debug errors plus pending glGetError codes); resets.
    GlErrorReport take();
    void record(const std::string& message);

private:
    std::mutex mutex_;
    GlErrorReport pending_;
};

}  // namespace nimbus::gpu
