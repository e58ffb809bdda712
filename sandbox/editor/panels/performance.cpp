// Performance and error: what the last viewport frame cost per pass (the stats `sandbox render
// --stats` writes), particle counts, the mode and quality selectors, the frame budget, and the
// reference snapshot with its error against the real-time frame.
#include <imgui.h>

#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "services/reference_snapshot.h"
#include "viewport_panel.h"
#include "nimbus/base/error.h"
#include "nimbus/base/settings.h"
#include "nimbus/gpu/pass_timer.h"
#include "nimbus/media/ecs/media_plugin.h"
#include "panels.h"

namespace nimbus::sandbox::editor {
namespace {

void frameStats(EditorState& state, const ViewportPanel& viewport) {
    const double ms = viewport.lastFrameMs();
    ImGui::Text("viewport %dx%d: %.1f ms (%.1f fps)", viewport.size().x, viewport.size().y, ms, ms > 0 ? 1000.0 / ms : 0.0);
    const auto* media = state.session().app().world().tryResource<media::ecs::MediaRendererState>();
    if (media && media->renderer) {
        const auto& s = media->renderer->stats();
        ImGui::Text("particles %zu, slices %d x %d texels, media scale %.2f", s.particles, s.slices, s.sliceResolution, s.mediaScale);
    }
    if (!ImGui::TreeNodeEx("passes (ms)", ImGuiTreeNodeFlags_DefaultOpen)) return;
    for (const auto& [name, samples] : viewport.timer().samples())
        ImGui::Text("%-28s %7.2f", name.c_str(), gpu::median(samples));
    ImGui::TreePop();
}

void selectors(EditorState& state, std::optional<std::string>& error) {
    const auto combo = [&](const char* label, const std::string& value, const std::vector<std::string>& options, auto&& apply) {
        if (!ImGui::BeginCombo(label, value.empty() ? "(default)" : value.c_str())) return;
        for (const std::string& option : options)
            if (ImGui::Selectable(option.c_str(), value == option) && value != option) {
                try {
                    apply(option);
                } catch (const InputError& e) {
                    error = e.what();
                }
            }
        ImGui::EndCombo();
    };
    ImGui::SetNextItemWidth(140);
    // Both from the declarations: the tiers' names and the technique table's modes.
    const Settings& settings = state.session().app().resource<Settings>();
    const auto words = [&](const char* key) { return settings.declared(key) ? settings.find(key)->words : std::vector<std::string>{}; };
    combo("quality", state.view().quality, words("quality"), [&](const std::string& q) { state.setQuality(q); });
    ImGui::SameLine();
    ImGui::SetNextItemWidth(140);
    combo("mode", state.view().mode, words("mode"), [&](const std::string& m) { state.setMode(m); });
}

// One widget per declared setting (nimbus/base/setting_spec.h), its kind from the spec's type: a
// combo of the words (on/off for booleans), else a text field whose hint is the default. What it
// shows is what the view sets; "(default)" unsets it.
void settingWidget(EditorState& state, const SettingSpec& spec, std::optional<std::string>& error) {
    std::string current;
    for (const std::string& s : state.view().settings)
        if (s.rfind(spec.key + "=", 0) == 0) current = s.substr(spec.key.size() + 1);
    const auto apply = [&](const std::string& value) {
        try {
            state.setSetting(spec.key, value);
        } catch (const InputError& e) {
            error = e.what();
        }
    };
    ImGui::SetNextItemWidth(160);
    if (spec.type == SettingType::Boolean || spec.type == SettingType::Choice) {
        static const std::vector<std::string> kOnOff{"on", "off"};
        const std::vector<std::string>& words = spec.type == SettingType::Boolean ? kOnOff : spec.words;
        if (ImGui::BeginCombo(spec.key.c_str(), current.empty() ? "(default)" : current.c_str())) {
            if (ImGui::Selectable("(default)", current.empty()) && !current.empty()) apply("");
            for (const std::string& w : words)
                if (ImGui::Selectable(w.c_str(), w == current) && w != current) apply(w);
            ImGui::EndCombo();
        }
    } else {
        char text[64];
        std::snprintf(text, sizeof text, "%s", current.c_str());
        const std::string hint = spec.defaultValue.empty() ? acceptedValues(spec) : spec.defaultValue;
        if (ImGui::InputTextWithHint(spec.key.c_str(), hint.c_str(), text, sizeof text, ImGuiInputTextFlags_EnterReturnsTrue))
            apply(text);
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", describeSetting(spec).c_str());
}

// Every setting but the two selectors above that acts in the current mode.
void settingsSection(EditorState& state, std::optional<std::string>& error) {
    if (!ImGui::TreeNode("settings")) return;
    const Settings& settings = state.session().app().resource<Settings>();
    const SettingSpec* modeSpec = settings.find("mode");
    const std::string mode = settings.text("mode").value_or(modeSpec != nullptr ? modeSpec->defaultValue : std::string());
    for (const SettingSpec& spec : settings.declarations())
        if (spec.key != "quality" && spec.key != "mode" && (spec.modes.empty() || settingActsIn(spec, mode, kEveryTier)))
            settingWidget(state, spec, error);
    ImGui::TreePop();
}

// While it refines, the picture so far is shown and judged: its paths per pixel and noise beside
// its error, so a user sees when the error is no longer the judge's noise.
void referenceSection(EditorState& state, const ReferenceSnapshot& snapshot, PerformanceRequest& request) {
    ImGui::BeginDisabled(snapshot.running());
    if (ImGui::Button("Reference snapshot")) request.takeReference = true;
    ImGui::EndDisabled();
    ImGui::SameLine();
    const auto* result = snapshot.result();
    if (snapshot.running()) {
        if (ImGui::Button("Stop")) request.stopReference = true;
        ImGui::SameLine();
        ImGui::ProgressBar(static_cast<float>(snapshot.progress()), ImVec2(-1, 0));
    } else if (!result) {
        ImGui::TextDisabled("renders `sandbox reference` of this view and time");
        return;
    }
    if (!result) return;
    if (snapshot.revision() != state.revision()) {
        ImGui::TextDisabled("out of date: the scene or view changed since");
        return;
    }
    ImGui::Text("rel-RMSE %.4g  PSNR %.1f dB  p99 |d| %.3g  (%.1f s)", result->metrics.relRmse, result->metrics.psnr,
                result->metrics.p99Abs, result->seconds);
    if (result->paths > 0) ImGui::Text("%d paths/pixel, noise %.2f%% of the mean", result->paths, 100.0 * result->relativeNoise);
}

}  // namespace

std::optional<std::string> drawPerformance(EditorState& state, const ViewportPanel& viewport, const ReferenceSnapshot& snapshot,
                                           double& budgetMs, PerformanceRequest& request) {
    std::optional<std::string> error;
    selectors(state, error);
    settingsSection(state, error);
    ImGui::SetNextItemWidth(140);
    ImGui::InputDouble("budget (ms)", &budgetMs, 5.0, 50.0, "%.0f");
    ImGui::SameLine();
    if (ImGui::Button("Fit to budget")) request.applyBudget = true;
    referenceSection(state, snapshot, request);
    ImGui::Separator();
    frameStats(state, viewport);
    return error;
}

}  // namespace nimbus::sandbox::editor
