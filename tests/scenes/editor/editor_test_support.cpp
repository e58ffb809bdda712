#include "editor_test_support.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

extern char** environ;

namespace nimbus::test {
namespace {

// One Xvfb server for the whole test program, started on first use. Xvfb picks a free display
// itself (-displayfd), which per-run `xvfb-run -a` does racily (and its clean-up can fail with
// exit 5 under load).
class VirtualDisplay {
public:
    VirtualDisplay() {
        int fds[2];
        if (pipe(fds) != 0) throw std::runtime_error("pipe failed");
        pid_ = fork();
        if (pid_ == 0) {
            close(fds[0]);
            const std::string fd = std::to_string(fds[1]);
            execl(NIMBUS_XVFB, "Xvfb", "-displayfd", fd.c_str(), "-screen", "0", "1920x1200x24", "-nolisten", "tcp",
                  static_cast<char*>(nullptr));
            _exit(127);
        }
        close(fds[1]);
        std::string number;
        char c = 0;
        while (read(fds[0], &c, 1) == 1 && c != '\n') number += c;
        close(fds[0]);
        if (pid_ < 0 || number.empty()) throw std::runtime_error("Xvfb did not start (" NIMBUS_XVFB ")");
        display_ = ":" + number;
    }
    ~VirtualDisplay() {
        kill(pid_, SIGTERM);
        waitpid(pid_, nullptr, 0);
    }
    const std::string& display() const { return display_; }

private:
    pid_t pid_ = -1;
    std::string display_;
};

const std::string& display() {
    static VirtualDisplay server;  // lives until the test program exits
    return server.display();
}

}  // namespace

ProcessResult runEditor(const TempFolder& dir, const std::filesystem::path& scene, const std::vector<std::string>& lines,
                        const std::string& viewportSize, const std::vector<std::string>& extra) {
    const auto script = dir / "script.txt";
    {
        std::ofstream out(script);
        for (const std::string& line : lines) out << line << '\n';
    }
    // The recent-files list goes to the test's folder, not the user's.
    std::vector<std::string> args = {"DISPLAY=" + display(), "XDG_CONFIG_HOME=" + (dir / "config").string(),
                                     sandboxExecutable().string(), "edit"};
    if (!scene.empty()) args.push_back(scene.string());
    args.insert(args.end(), {"--script", script.string(), "--viewport-size", viewportSize});
    args.insert(args.end(), extra.begin(), extra.end());
    return runProcess("/usr/bin/env", args);
}

assets::RgbImage renderWithSandbox(const TempFolder& dir, const std::filesystem::path& scene, const std::string& size, double time) {
    const auto out = dir / ("sandbox_" + scene.stem().string() + ".exr");
    const ProcessResult r = runProcess(sandboxExecutable(), {"render", scene.string(), "--size", size, "--quality", "fast",
                                                             "--time", std::to_string(time), "--out", out.string()});
    if (r.exitCode != 0) throw std::runtime_error("sandbox render failed: " + r.err);
    return assets::readImage(out);
}

RunningEditor::RunningEditor(const TempFolder& dir, const std::filesystem::path& scene, const std::string& viewportSize)
    : errFile_(dir / "editor.err") {
    std::vector<std::string> args = {"/usr/bin/env", "DISPLAY=" + display(), "XDG_CONFIG_HOME=" + (dir / "config").string(),
                                     sandboxExecutable().string(), "edit", scene.string(), "--viewport-size", viewportSize};
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    const std::string out = (dir / "editor.out").string();
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, errFile_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    pid_t pid = -1;
    const int spawned = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (spawned != 0) throw std::runtime_error("cannot start the editor");
    pid_ = pid;
}

RunningEditor::~RunningEditor() {
    if (pid_ <= 0) return;
    kill(pid_, SIGTERM);
    waitpid(pid_, nullptr, 0);
}

bool RunningEditor::running() {
    if (pid_ <= 0) return false;
    if (waitpid(pid_, nullptr, WNOHANG) == 0) return true;
    pid_ = -1;
    return false;
}

std::string RunningEditor::err() const {
    std::ifstream in(errFile_);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

ProcessResult xdotool(const std::vector<std::string>& args, int seconds) {
    std::vector<std::string> all = {std::to_string(seconds), "/usr/bin/env", "DISPLAY=" + display(), NIMBUS_XDOTOOL};
    all.insert(all.end(), args.begin(), args.end());
    return runProcess("/usr/bin/timeout", all);
}

double numberAfter(const std::string& text, const std::string& key) {
    const auto at = text.find(key);
    if (at == std::string::npos) return std::nan("");
    std::istringstream in(text.substr(at + key.size()));
    double value = std::nan("");
    in >> value;
    return value;
}

}  // namespace nimbus::test
