// sandbox settings
// Lists every setting `--set KEY=VALUE` and a scene's render block accept, with its help text, and
// what each quality tier picks. The list is the App's own declarations, so it cannot drift.
#include <cstdio>

#include "commands.h"
#include "nimbus/base/settings.h"
#include "nimbus/ecs/app.h"
#include "nimbus/media/ecs/media_plugin.h"
#include "nimbus/render/render_plugin.h"

namespace nimbus::sandbox {

CommandRunner addSettingsCommand(CLI::App& app) {
    app.add_subcommand("settings", "list the renderer's settings (--set KEY=VALUE, a scene's render block) and the quality tiers");
    return [] {
        ecs::App host;
        host.insertResource<Settings>();
        host.addPlugin<render::RenderPlugin>();
        host.addPlugin<media::ecs::MediaPlugin>();
        for (const Settings::Declaration& d : host.resource<Settings>().declarations())
            std::printf("%-20s %s\n", d.key.c_str(), d.help.c_str());
        std::printf("\nquality tiers (a setting given explicitly wins over its tier):\n");
        for (const media::ecs::QualityPreset& preset : media::ecs::kQualityPresets) {
            std::printf("  %-10s", preset.name);
            if (preset.settings.empty()) std::printf(" every setting at its default");
            for (const auto& [key, value] : preset.settings) std::printf(" %s=%s", key.c_str(), value.c_str());
            std::printf("\n");
        }
        return 0;
    };
}

}  // namespace nimbus::sandbox
