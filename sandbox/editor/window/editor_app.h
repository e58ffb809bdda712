#pragma once
// `sandbox edit`: the editor's window. It owns the GL window, Dear ImGui and the panels, runs the
// frame loop (input, playback, viewport render, UI), and carries out script commands that need the
// window (frames, screenshots, viewport images, reference snapshots).
//
// Does not: edit anything itself: every change goes through EditorState.
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include <glm/glm.hpp>

#include "editor_state.h"
#include "nimbus/gpu/context.h"
#include "panels/panels.h"
#include "panels/viewport_panel.h"
#include "services/recent_files.h"
#include "services/reference_snapshot.h"
#include "script.h"

namespace nimbus::sandbox::editor {

struct EditorOptions {
    std::filesystem::path scene;            // empty: a new scene
    std::optional<glm::ivec2> viewportSize; // fixed viewport size (scripts, benchmarks)
    ViewSettings view;
    double budgetMs = 0.0;                  // > 0: walk the quality ladder to fit it once the scene is open
};

class EditorApp final : public ScriptTarget {
public:
    explicit EditorApp(const EditorOptions& options);
    ~EditorApp() override;

    // The interactive loop, until the window closes. Returns the exit code.
    int run();
    // Runs the script line by line in the live window, then closes. Exits non-zero on the first
    // failing command (printing its reason), with the state as it was before that command.
    int runScript(const std::filesystem::path& script);

    // ScriptTarget
    EditorState& state() override { return *state_; }
    void renderFrames(int count) override;
    void play(double seconds) override;
    void screenshot(const std::filesystem::path& file) override;
    void writeViewport(const std::filesystem::path& file) override;
    void reference(const std::filesystem::path& file) override;
    void viewThrough(const std::string& camera) override;
    void quit() override { quit_ = true; }

private:
    void frame(bool forceRender);
    void drawWindows();
    void layoutWindow(const char* name, float x, float y, float w, float h);
    void shortcuts();
    void showTitle();
    void applyBudget();
    void report(const std::optional<std::string>& error);
    // The button's snapshot refines until this many paths per pixel, or Stop; a script's `reference`
    // stops at `sandbox reference`'s default.
    static constexpr int kInteractivePaths = 1024;
    void startReference(int paths);
    void initImGui();

    std::unique_ptr<gpu::Context> context_;
    std::unique_ptr<EditorState> state_;
    std::unique_ptr<ViewportPanel> viewport_;
    ReferenceSnapshot snapshot_;
    FieldWidgets fields_;
    RecentFiles recent_;
    FilesMenu menu_;
    Playback playback_;
    std::string renameBuffer_;
    double budgetMs_ = 0.0;
    PerformanceRequest request_;
    std::string status_;
    std::string title_;
    bool statusIsError_ = false;
    std::optional<std::filesystem::path> pendingScreenshot_;
    bool quit_ = false;
};

}  // namespace nimbus::sandbox::editor
