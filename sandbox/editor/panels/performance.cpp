// Performance and error: what the last viewport frame cost per pass (the stats `sandbox render
// --stats` writes), particle counts, the mode and quality selectors, the frame budget, and the
// reference snapshot with its error against the real-time frame.
#include <imgui.h>

#include "services/reference_snapshot.h"
#include "viewport_panel.h"
#include "nimbus/base/error.h"
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
    const auto combo = [&](const char* label, const std::string& value, std::initializer_list<const char*> options, auto&& apply) {
        if (!ImGui::BeginCombo(label, value.empty() ? "(default)" : value.c_str())) return;
        for (const char* option : options)
            if (ImGui::Selectable(option, value == option) && value != option) {
                try {
                    apply(option);
                } catch (const InputError& e) {
                    error = e.what();
                }
            }
        ImGui::EndCombo();
    };
    ImGui::SetNextItemWidth(140);
    combo("quality", state.view().quality, {"fast", "balanced", "exact"}, [&](const char* q) { state.setQuality(q); });
    ImGui::SameLine();
    ImGui::SetNextItemWidth(140);
    combo("mode", state.view().mode, {"particles", "blocks", "raymarch", "billboards"}, [&](const char* m) { state.setMode(m); });
}

void referenceSection(EditorState& state, const ReferenceSnapshot& snapshot, PerformanceRequest& request) {
    ImGui::BeginDisabled(snapshot.running());
    if (ImGui::Button("Reference snapshot")) request.takeReference = true;
    ImGui::EndDisabled();
    ImGui::SameLine();
    if (snapshot.running()) {
        ImGui::ProgressBar(static_cast<float>(snapshot.progress()), ImVec2(-1, 0));
        return;
    }
    const auto* result = snapshot.result();
    if (!result) {
        ImGui::TextDisabled("renders `sandbox reference` of this view and time");
        return;
    }
    if (snapshot.revision() != state.revision()) {
        ImGui::TextDisabled("out of date: the scene or view changed since");
        return;
    }
    ImGui::Text("rel-RMSE %.4g  PSNR %.1f dB  p99 |d| %.3g  (%.1f s)", result->metrics.relRmse, result->metrics.psnr,
                result->metrics.p99Abs, result->seconds);
}

}  // namespace

std::optional<std::string> drawPerformance(EditorState& state, const ViewportPanel& viewport, const ReferenceSnapshot& snapshot,
                                           double& budgetMs, PerformanceRequest& request) {
    std::optional<std::string> error;
    selectors(state, error);
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
