#pragma once
// Test helper: run a program (the sandbox) as a user would, capturing stdout, stderr and how it
// ended. posix_spawn with both streams redirected to files, so a chatty child can never block on
// a full pipe.
#include <filesystem>
#include <string>
#include <vector>

namespace nimbus::test {

struct ProcessResult {
    int exitCode = -1;   // valid when !signaled
    bool signaled = false;
    int signal = 0;      // the signal that killed it, when signaled
    std::string out;
    std::string err;
    bool timedOut = false;  // killed after the time limit runProcess was given
    double seconds = 0.0;   // wall time from start to exit

    // "exit 2" or "killed by signal 11 (Segmentation fault)", for failure messages.
    std::string describe() const;
    // stderr split into lines (a trailing newline does not make an empty line).
    std::vector<std::string> errLines() const;
};

// Exit code, signal, stdout and stderr in one message for assertion failures.
inline std::string explain(const ProcessResult& r) { return r.describe() + "\nstdout:\n" + r.out + "\nstderr:\n" + r.err; }

// Runs `program` with `args` (argv[1..]) and waits for it, at most `limitSeconds` when that is
// > 0 (then it is killed, signaled and timedOut). Throws std::runtime_error when it cannot be
// started at all.
ProcessResult runProcess(const std::filesystem::path& program, const std::vector<std::string>& args, double limitSeconds = 0.0);

// The sandbox executable these tests were built beside (NIMBUS_SANDBOX_EXE).
std::filesystem::path sandboxExecutable();

// A fresh folder under the system temp dir for one test's outputs, removed at the end of the test.
class TempFolder {
public:
    TempFolder();
    ~TempFolder();
    TempFolder(const TempFolder&) = delete;
    TempFolder& operator=(const TempFolder&) = delete;
    const std::filesystem::path& path() const { return path_; }
    std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

private:
    std::filesystem::path path_;
};

}  // namespace nimbus::test
