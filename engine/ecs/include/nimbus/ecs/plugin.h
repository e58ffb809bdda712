#pragma once
// A plugin adds a feature to an App in one place: build() registers its components, resources,
// phases and systems (and may add the plugins it depends on). Plugins are identified by name():
// an App builds each name once.
#include <string_view>

namespace nimbus::ecs {

class App;

class Plugin {
public:
    virtual ~Plugin();
    virtual std::string_view name() const = 0;
    virtual void build(App& app) = 0;

protected:
    Plugin() = default;
    Plugin(const Plugin&) = default;
    Plugin& operator=(const Plugin&) = default;
};

}  // namespace nimbus::ecs
