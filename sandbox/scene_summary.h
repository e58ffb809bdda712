#pragma once
// What `sandbox validate` reports for a scene once the session has loaded, checked and simulated
// it: its contents, its camera, its particles and the shadow views and light slices each light
// needs. Shared with the loader's fuzz target (tests/fuzz), so the fuzzer walks what validate walks.
#include <string>

#include "session.h"

namespace nimbus::sandbox {

// The report, a few lines each ending in '\n'; `name` heads it ("scene.gltf: valid glTF 2.0").
std::string summarizeScene(Session& session, const std::string& name);

}  // namespace nimbus::sandbox
