#include "editor_app.h"

#include <epoxy/gl.h>
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "frame_budget_walk.h"
#include "nimbus/base/error.h"
#include "nimbus/media/ecs/media_plugin.h"

namespace nimbus::sandbox::editor {
namespace {

constexpr float kOutlinerWidth = 270.0f, kInspectorWidth = 380.0f, kBottomHeight = 230.0f, kStatusHeight = 26.0f;
constexpr double kPlayStep = 1.0 / 30.0;  // playback advances scene time by one frame step per UI frame

// The window that fits a fixed viewport with the panels around it.
gpu::ContextDesc windowDesc(const EditorOptions& options) {
    gpu::ContextDesc desc{.kind = gpu::ContextKind::Window, .width = 1600, .height = 960, .title = "Nimbus editor"};
    if (options.viewportSize) {
        desc.width = std::max(1280, options.viewportSize->x + static_cast<int>(kOutlinerWidth + kInspectorWidth) + 20);
        desc.height = std::max(800, options.viewportSize->y + static_cast<int>(kBottomHeight + kStatusHeight) + 80);
    }
    return desc;
}

}  // namespace

EditorApp::EditorApp(const EditorOptions& options)
    : context_(gpu::Context::create(windowDesc(options))),
      state_(std::make_unique<EditorState>(options.view)),
      viewport_(std::make_unique<ViewportPanel>(options.viewportSize)),
      fields_(*state_),
      budgetMs_(options.budgetMs) {
    initImGui();
    if (!options.scene.empty()) {
        try {
            state_->open(options.scene);
            recent_.add(options.scene);
        } catch (const InputError& e) {
            std::fprintf(stderr, "sandbox edit: %s\n", e.what());
            report(std::string(e.what()));  // the editor stays up with an empty scene
        }
    }
    if (budgetMs_ > 0.0) applyBudget();
}

EditorApp::~EditorApp() {
    snapshot_.cancel();
    viewport_.reset();
    state_.reset();  // GL objects go while the context is alive
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
}

void EditorApp::initImGui() {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // the layout is fixed by the code, not remembered
    ImGui::StyleColorsDark();
    ImGui_ImplGlfw_InitForOpenGL(static_cast<GLFWwindow*>(context_->nativeWindow()), true);
    ImGui_ImplOpenGL3_Init(nullptr);  // the backend's own GLSL, which Mesa's 4.5 core profile compiles
    glfwSwapInterval(0);  // the viewport's cost is what we measure, not the display's refresh
}

void EditorApp::report(const std::optional<std::string>& error) {
    if (!error) return;
    status_ = *error;
    statusIsError_ = true;
}

int EditorApp::run() {
    while (!quit_ && !menu_.quit) {
        if (context_->shouldClose()) {
            glfwSetWindowShouldClose(static_cast<GLFWwindow*>(context_->nativeWindow()), GLFW_FALSE);
            requestQuit(*state_, menu_);
        }
        frame(false);
    }
    return 0;
}

int EditorApp::runScript(const std::filesystem::path& script) {
    const std::vector<ScriptLine> lines = readScript(script);
    frame(true);
    for (const ScriptLine& line : lines) {
        try {
            runScriptLine(*this, script, line);
        } catch (const InputError& e) {
            std::fprintf(stderr, "sandbox edit: %s\n", e.what());
            return 2;
        }
        frame(false);
        if (quit_) break;
    }
    return 0;
}

void EditorApp::frame(bool forceRender) {
    context_->pollEvents();
    try {
        if (playback_.playing) {
            if (state_->time() + kPlayStep > playback_.end + 1e-9) {
                if (playback_.loop) state_->scrub(0.0);
                else playback_.playing = false;
            } else {
                state_->advance(kPlayStep);
            }
        }
        if (snapshot_.running() && snapshot_.revision() != state_->revision()) snapshot_.cancel();
        snapshot_.update();
        viewport_->render(*state_, forceRender);
    } catch (const InputError& e) {
        report(std::string(e.what()));
        playback_.playing = false;
    }
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    drawWindows();
    ImGui::Render();
    int width = 0, height = 0;
    context_->framebufferSize(width, height);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, width, height);
    glClearColor(0.1f, 0.1f, 0.11f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    if (pendingScreenshot_) {
        std::vector<std::uint8_t> pixels(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3);
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, pixels.data());
        glPixelStorei(GL_PACK_ALIGNMENT, 4);
        std::vector<std::uint8_t> flipped(pixels.size());  // GL rows start at the bottom, images at the top
        const std::size_t row = static_cast<std::size_t>(width) * 3;
        for (int y = 0; y < height; ++y)
            std::copy_n(pixels.begin() + static_cast<std::ptrdiff_t>(row * static_cast<std::size_t>(height - 1 - y)), row,
                        flipped.begin() + static_cast<std::ptrdiff_t>(row * static_cast<std::size_t>(y)));
        const auto file = *pendingScreenshot_;
        pendingScreenshot_.reset();
        assets::writeDisplayPixels(file, width, height, flipped);
    }
    context_->swapBuffers();
}

void EditorApp::layoutWindow(const char* name, float x, float y, float w, float h) {
    ImGui::SetNextWindowPos(ImVec2(x, y));
    ImGui::SetNextWindowSize(ImVec2(std::max(w, 50.0f), std::max(h, 50.0f)));
    ImGui::Begin(name, nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
}

void EditorApp::drawWindows() {
    report(drawMenuBar(*state_, menu_, recent_, *viewport_));
    if (auto notice = state_->takeNotice()) {
        status_ = *notice;
        statusIsError_ = false;
    }
    shortcuts();
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const float top = ImGui::GetFrameHeight();
    const float middle = display.x - kOutlinerWidth - kInspectorWidth;
    const float bottom = display.y - kStatusHeight - kBottomHeight;

    layoutWindow("Outliner", 0, top, kOutlinerWidth, display.y - top - kStatusHeight);
    report(drawOutliner(*state_, viewport_->pointAhead(*state_, 4.0), renameBuffer_));
    ImGui::End();

    layoutWindow("Inspector", display.x - kInspectorWidth, top, kInspectorWidth, display.y - top - kStatusHeight);
    drawInspector(*state_, fields_);
    report(fields_.takeError());
    ImGui::End();

    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(2, 2));
    layoutWindow("Viewport", kOutlinerWidth, top, middle, bottom - top);
    ImGui::PopStyleVar();
    report(viewport_->draw(*state_, snapshot_));
    ImGui::End();

    layoutWindow("Timeline", kOutlinerWidth, bottom, middle * 0.45f, kBottomHeight);
    report(drawTimeline(*state_, playback_));
    ImGui::End();

    layoutWindow("Performance and error", kOutlinerWidth + middle * 0.45f, bottom, middle * 0.55f, kBottomHeight);
    request_ = {};
    report(drawPerformance(*state_, *viewport_, snapshot_, budgetMs_, request_));
    ImGui::End();
    if (request_.takeReference) startReference(kInteractivePaths);
    if (request_.stopReference) snapshot_.stop();
    if (request_.applyBudget) applyBudget();

    layoutWindow("Status", 0, display.y - kStatusHeight, display.x, kStatusHeight);
    const std::string file = state_->document().isUntitled() ? "(untitled)" : state_->document().path().string();
    showTitle();
    ImGui::Text("%s%s | t = %.2f s |", file.c_str(), state_->dirty() ? " *" : "", state_->time());
    ImGui::SameLine();
    if (statusIsError_) ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.35f, 1.0f), "%s", status_.c_str());
    else ImGui::TextUnformatted(status_.c_str());
    ImGui::End();
}

// The window's title names the file and marks unsaved changes, as the status bar does, once the
// frame that shows them is drawn: "smoke.gltf* - Nimbus editor".
void EditorApp::showTitle() {
    const std::string name = state_->document().isUntitled() ? "(untitled)" : state_->document().path().filename().string();
    std::string title = name + (state_->dirty() ? "*" : "") + " - Nimbus editor";
    if (title == title_) return;
    glfwSetWindowTitle(static_cast<GLFWwindow*>(context_->nativeWindow()), title.c_str());
    title_ = std::move(title);
}

void EditorApp::shortcuts() {
    const ImGuiIO& io = ImGui::GetIO();
    if (io.WantTextInput) return;
    try {
        if (io.KeyCtrl && ImGui::IsKeyPressed(GLFW_KEY_Z, false)) state_->undo();
        if (io.KeyCtrl && ImGui::IsKeyPressed(GLFW_KEY_Y, false)) state_->redo();
        if (io.KeyCtrl && ImGui::IsKeyPressed(GLFW_KEY_S, false) && !state_->document().isUntitled()) state_->save();
        if (io.KeyCtrl && ImGui::IsKeyPressed(GLFW_KEY_O, false)) menu_.showOpen = true;
        if (ImGui::IsKeyPressed(GLFW_KEY_DELETE, false) && state_->selected() >= 0) state_->removeSelected();
        if (ImGui::IsKeyPressed(GLFW_KEY_SPACE, false)) playback_.playing = !playback_.playing;
    } catch (const InputError& e) {
        report(std::string(e.what()));
    }
}

void EditorApp::startReference(int paths) {
    viewport_->render(*state_, false);
    snapshot_.start(state_->session(), viewport_->freeCamera() ? "" : viewport_->sceneCamera(), viewport_->cameraOverride(),
                    viewport_->image(*state_), state_->revision(), paths);
}

// Walks the quality ladder with the viewport's size, then keeps the chosen rung as the view's settings.
void EditorApp::applyBudget() {
    if (!(budgetMs_ > 0.0)) return report(std::string("the frame budget must be > 0 ms"));
    viewport_->render(*state_, true);
    const BudgetChoice choice = settleOnBudget(state_->session().app(), budgetMs_);
    ViewSettings view = state_->view();
    for (const auto& rung : media::ecs::kQualityLadder) {
        if (choice.rung != rung.name) continue;
        for (const auto& [key, value] : rung.assignments()) {
            if (key == "quality") {
                view.quality = value;
                continue;
            }
            std::erase_if(view.settings, [&, k = key](const std::string& s) { return s.rfind(k + "=", 0) == 0; });
            view.settings.push_back(key + "=" + value);
        }
    }
    state_->setView(view);
    status_ = "budget " + std::to_string(static_cast<int>(budgetMs_)) + " ms: " + choice.rung;
    statusIsError_ = false;
}

// ---- script commands that need the window ---------------------------------------------------

void EditorApp::renderFrames(int count) {
    const int before = viewport_->renderedFrames();
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < count; ++i) frame(true);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("frames %d: %.1f ms per frame (%.2f fps) at %dx%d\n", viewport_->renderedFrames() - before,
                1000.0 * seconds / count, count / seconds, viewport_->size().x, viewport_->size().y);
    std::fflush(stdout);
}

void EditorApp::play(double seconds) {
    if (!(seconds > 0.0) || seconds > 1e5) throwInputError("", "play", "", "needs a duration in (0, 1e5] s");
    const int steps = static_cast<int>(std::lround(seconds / kPlayStep));
    for (int i = 0; i < steps; ++i) {
        state_->advance(kPlayStep);
        frame(false);
    }
}

void EditorApp::screenshot(const std::filesystem::path& file) {
    pendingScreenshot_ = file;
    frame(false);
}

void EditorApp::writeViewport(const std::filesystem::path& file) {
    viewport_->render(*state_, false);
    assets::writeImage(file, viewport_->image(*state_));
}

void EditorApp::reference(const std::filesystem::path& file) {
    startReference(ReferenceSnapshot::kDefaultPaths);
    while (snapshot_.running()) frame(false);
    snapshot_.update();
    const auto* result = snapshot_.result();
    if (!result) throwInputError("", "reference", "", "the snapshot was cancelled");
    std::printf("reference: rel_rmse %.9g psnr %.6g p99_abs %.9g paths %d noise %.4g (%.1f s)\n", result->metrics.relRmse,
                result->metrics.psnr, result->metrics.p99Abs, result->paths, result->relativeNoise, result->seconds);
    std::fflush(stdout);
    if (!file.empty()) assets::writeImage(file, result->reference);
}

void EditorApp::viewThrough(const std::string& camera) {
    if (camera == "-") return viewport_->useFreeCamera(*state_);
    const assets::Scene& scene = state_->session().scene();
    const bool known = camera.empty() || std::any_of(scene.nodes.begin(), scene.nodes.end(), [&](const assets::Node& n) {
        return n.camera >= 0 && (n.name == camera || scene.cameras[static_cast<std::size_t>(n.camera)].name == camera);
    });
    if (!known) throwInputError("", "camera", "", "no camera or camera node is named '" + camera + "'");
    viewport_->viewThrough(camera);
    viewport_->render(*state_, true);  // an unknown camera fails here, naming it
}

}  // namespace nimbus::sandbox::editor
