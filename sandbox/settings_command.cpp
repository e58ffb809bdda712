// sandbox settings [--schema]
// Lists every setting `--set KEY=VALUE` and a scene's render block accept: its help text, what it
// accepts, its default, and the modes and tiers it acts in. The list is the App's own
// declarations (nimbus/base/setting_spec.h), so it cannot drift. --schema prints the JSON schema of
// a scene's render block from the same declarations (docs/scene-format.schema.json holds it).
#include <cstdio>

#include <nlohmann/json.hpp>

#include "commands.h"
#include "nimbus/base/settings.h"
#include "nimbus/ecs/app.h"
#include "nimbus/media/ecs/media_plugin.h"
#include "nimbus/render/render_plugin.h"
#include "settings_listing.h"

namespace nimbus::sandbox {

CommandRunner addSettingsCommand(CLI::App& app) {
    auto* cmd = app.add_subcommand("settings", "list the renderer's settings (--set KEY=VALUE, a scene's render block) and where each acts");
    auto schema = std::make_shared<bool>(false);
    cmd->add_flag("--schema", *schema, "print the JSON schema of a scene's render block instead");
    return [schema] {
        ecs::App host;
        host.insertResource<Settings>();
        host.addPlugin<render::RenderPlugin>();
        host.addPlugin<media::ecs::MediaPlugin>();
        const Settings& settings = host.resource<Settings>();
        if (*schema) std::printf("%s\n", renderBlockSchema(settings).dump(2).c_str());
        else std::fputs(listSettings(settings).c_str(), stdout);
        return 0;
    };
}

}  // namespace nimbus::sandbox
