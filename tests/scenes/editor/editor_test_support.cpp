#include "editor_test_support.h"

#include <cmath>
#include <fstream>
#include <sstream>

namespace nimbus::test {

ProcessResult runEditor(const TempFolder& dir, const std::filesystem::path& scene, const std::vector<std::string>& lines,
                        const std::string& viewportSize, const std::vector<std::string>& extra) {
    const auto script = dir / "script.txt";
    {
        std::ofstream out(script);
        for (const std::string& line : lines) out << line << '\n';
    }
    std::vector<std::string> args = {"-a", "-s", "-screen 0 1920x1200x24", sandboxExecutable().string(), "edit"};
    if (!scene.empty()) args.push_back(scene.string());
    args.insert(args.end(), {"--script", script.string(), "--viewport-size", viewportSize});
    args.insert(args.end(), extra.begin(), extra.end());
    // The recent-files list goes to the test's folder, not the user's.
    return runProcess("/usr/bin/env", [&] {
        std::vector<std::string> env = {"XDG_CONFIG_HOME=" + (dir / "config").string(), NIMBUS_XVFB_RUN};
        env.insert(env.end(), args.begin(), args.end());
        return env;
    }());
}

assets::RgbImage renderWithSandbox(const TempFolder& dir, const std::filesystem::path& scene, const std::string& size, double time) {
    const auto out = dir / ("sandbox_" + scene.stem().string() + ".exr");
    const ProcessResult r = runProcess(sandboxExecutable(), {"render", scene.string(), "--size", size, "--quality", "fast",
                                                             "--time", std::to_string(time), "--out", out.string()});
    if (r.exitCode != 0) throw std::runtime_error("sandbox render failed: " + r.err);
    return assets::readImage(out);
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
