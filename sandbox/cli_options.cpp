#include "cli_options.h"

#include <charconv>
#include <cmath>

#include "nimbus/base/error.h"
#include "nimbus/base/settings.h"
#include "nimbus/ecs/app.h"
#include "nimbus/media/ecs/media_plugin.h"
#include "nimbus/render/render_plugin.h"
#include "nimbus/scene/scene_plugin.h"

namespace nimbus::sandbox {
namespace {

double defaultTimeStep() { return ecs::AppDesc{}.fixedTimeStep; }

// The number `text` spells, whole or not; std::nullopt for anything else (trailing text included).
std::optional<double> readNumber(const std::string& text) {
    double value = 0.0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec == std::errc::result_out_of_range) return HUGE_VAL;  // "1e999": beyond every range
    if (ec != std::errc() || end != text.data() + text.size() || text.empty()) return std::nullopt;
    return value;
}

}  // namespace

double parseTime(const std::string& text, const std::string& option) {
    const auto value = readNumber(text);
    if (!value) throwInputError(option, typedText(text), "", "expected a number of seconds >= 0");
    (void)scene::simulationSteps(*value, defaultTimeStep(), option);
    return *value;
}

std::string timeHelp(const std::string& what) {
    const double maxSeconds = static_cast<double>(scene::kMaxSimulationSteps) * defaultTimeStep();
    return what + " (0.." + formatSettingNumber(maxSeconds) + ": at most " + formatSettingNumber(static_cast<double>(scene::kMaxSimulationSteps)) +
           " steps of " + formatSettingNumber(defaultTimeStep()) + " s; a long simulation shows its progress)";
}

double parsePositive(const std::string& text, const std::string& option, double max, const std::string& unit) {
    const auto value = readNumber(text);
    const std::string expected = "expected a finite number in (0, " + formatSettingNumber(max) + "]" + (unit.empty() ? "" : " " + unit);
    if (!value || !std::isfinite(*value) || !(*value > 0.0) || *value > max) throwInputError(option, typedText(text), "", expected);
    return *value;
}

int parseCount(const std::string& text, const std::string& option, long long min, long long max) {
    long long value = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || end != text.data() + text.size() || text.empty() || value < min || value > max)
        throwInputError(option, typedText(text), "", "expected a whole number in " + std::to_string(min) + ".." + std::to_string(max));
    return static_cast<int>(value);
}

std::string settingOptionHelp(const std::string& key, const std::string& lead, const std::string& defaultText) {
    ecs::App host;  // the declarations a session makes, without a scene
    host.insertResource<Settings>();
    host.addPlugin<render::RenderPlugin>();
    host.addPlugin<media::ecs::MediaPlugin>();
    const SettingSpec* spec = host.resource<Settings>().find(key);
    if (spec == nullptr) throw std::logic_error("no setting '" + key + "' is declared");
    return lead + ": " + acceptedValues(*spec) + "; default " + defaultText + " (sandbox settings says what each does)";
}

CLI::Option* addTimeOption(CLI::App* cmd, std::string& text, const std::string& what) {
    return cmd->add_option("--time", text, timeHelp(what));
}

}  // namespace nimbus::sandbox
