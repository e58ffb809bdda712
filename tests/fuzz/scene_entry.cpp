// The loader's fuzz entry: the bytes as a scene file, then everything `sandbox validate` does.
#include <filesystem>
#include <memory>

#include "fuzz_entries.h"
#include "nimbus/assets/scene.h"
#include "nimbus/base/error.h"
#include "scene_summary.h"
#include "session.h"

namespace nimbus::fuzz {

void loadScene(const std::uint8_t* data, std::size_t size) {
    const std::filesystem::path file = "/nonexistent-nimbus-fuzz/scene.gltf";
    try {
        auto scene = std::make_shared<const assets::Scene>(assets::loadSceneFromMemory({data, data + size}, file));
        sandbox::SessionOptions options;
        options.time = kSceneTime;
        sandbox::Session session(scene, options);
        (void)sandbox::summarizeScene(session, file.string());
    } catch (const InputError&) {
        // Refused with its one-line reason: what bad input must get.
    }
}

}  // namespace nimbus::fuzz
