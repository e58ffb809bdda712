#pragma once
// What `sandbox settings` prints, from the declarations alone (nimbus/base/setting_spec.h): one line
// per key, and the JSON schema of a scene's render block (docs/scene-format.schema.json).
#include <string>

#include <nlohmann/json.hpp>

#include "nimbus/base/settings.h"

namespace nimbus::sandbox {

// "key  help; accepts; default; where", one line per declared key, in declaration order.
std::string listSettings(const Settings& settings);

// The render block's schema: an object whose properties are exactly the declared keys.
nlohmann::json renderBlockSchema(const Settings& settings);

}  // namespace nimbus::sandbox
