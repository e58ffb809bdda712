// The timeline: scene time with play, pause, step, scrub and loop. Scrubbing re-simulates from 0,
// so a scrubbed frame equals the played one.
#include <imgui.h>

#include <algorithm>
#include <cmath>

#include "nimbus/base/error.h"
#include "panels.h"

namespace nimbus::sandbox::editor {
namespace {

constexpr double kStep = 1.0 / 30.0;
constexpr double kZero = 0.0;

}  // namespace

std::optional<std::string> drawTimeline(EditorState& state, Playback& playback) {
    std::optional<std::string> error;
    try {
        if (ImGui::Button(playback.playing ? "Pause" : "Play")) playback.playing = !playback.playing;
        ImGui::SameLine();
        if (ImGui::Button("Step")) {
            playback.playing = false;
            state.advance(kStep);
        }
        ImGui::SameLine();
        if (ImGui::Button("|<")) {
            playback.playing = false;
            state.scrub(0.0);
        }
        ImGui::SameLine();
        ImGui::Checkbox("Loop", &playback.loop);
        ImGui::SameLine();
        ImGui::SetNextItemWidth(90);
        ImGui::InputDouble("end (s)", &playback.end, 1.0, 5.0, "%.1f");
        playback.end = std::clamp(playback.end, 0.1, 1e5);
        double t = state.time();
        ImGui::SetNextItemWidth(-1);
        if (ImGui::SliderScalar("##time", ImGuiDataType_Double, &t, &kZero, &playback.end, "t = %.3f s")) {
            playback.playing = false;
            state.scrub(std::round(t / kStep) * kStep);  // on the frame grid, like playing
        }
    } catch (const InputError& e) {
        error = e.what();
    }
    return error;
}

}  // namespace nimbus::sandbox::editor
