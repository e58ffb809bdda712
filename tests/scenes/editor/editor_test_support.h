#pragma once
// Running `sandbox edit` with a script on a private Xvfb display, for the editor's scene tests.
#include <filesystem>
#include <string>
#include <vector>

#include "nimbus/assets/image_io.h"
#include "process.h"

namespace nimbus::test {

inline const std::filesystem::path kContentScenes = std::filesystem::path(NIMBUS_CONTENT_DIR_FOR_TESTS) / "scenes";

// Writes `lines` to DIR/script.txt and runs the editor on `scene` with it at a fixed viewport size.
ProcessResult runEditor(const TempFolder& dir, const std::filesystem::path& scene, const std::vector<std::string>& lines,
                        const std::string& viewportSize = "128x72", const std::vector<std::string>& extra = {});

// `sandbox render` of the same scene as the editor's default view: fast quality.
assets::RgbImage renderWithSandbox(const TempFolder& dir, const std::filesystem::path& scene, const std::string& size,
                                   double time = 0.0);

// The number after `key` in `text` ("rel_rmse 0.036..."), NaN when absent.
double numberAfter(const std::string& text, const std::string& key);

// `sandbox edit SCENE --viewport-size WxH` in its window on the private display, with no script:
// driven by X input. Its output goes to DIR/editor.out and DIR/editor.err; it is ended
// (SIGTERM) when this goes out of scope.
class RunningEditor {
public:
    RunningEditor(const TempFolder& dir, const std::filesystem::path& scene, const std::string& viewportSize);
    ~RunningEditor();
    RunningEditor(const RunningEditor&) = delete;
    RunningEditor& operator=(const RunningEditor&) = delete;
    bool running();  // false once it exited
    std::string err() const;

private:
    int pid_ = -1;
    std::filesystem::path errFile_;
};

// xdotool (NIMBUS_XDOTOOL) on the private display, killed after `seconds` (a `search --sync` that
// never matches would wait for ever).
ProcessResult xdotool(const std::vector<std::string>& args, int seconds = 120);

}  // namespace nimbus::test
