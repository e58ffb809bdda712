// The settings' fuzz entry: --set, --mode and --quality as typed, and a scene's render block.
#include <algorithm>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "fuzz_entries.h"
#include "nimbus/assets/scene.h"
#include "nimbus/base/error.h"
#include "session.h"

namespace nimbus::fuzz {
namespace {

constexpr char kScene[] = NIMBUS_FUZZ_CONTENT_DIR "/scenes/smoke.gltf";

const nlohmann::json& sceneJson() {
    static const nlohmann::json json = [] {
        std::ifstream in(kScene);
        return nlohmann::json::parse(in);
    }();
    return json;
}

// The scene with `block` as its medium's render block.
std::vector<unsigned char> sceneWithRenderBlock(const nlohmann::json& block) {
    nlohmann::json json = sceneJson();
    for (auto& node : json["nodes"])
        if (node.contains("extensions") && node["extensions"].contains(assets::kMediaExtension))
            node["extensions"][assets::kMediaExtension]["render"] = block;
    const std::string text = json.dump();
    return {text.begin(), text.end()};
}

}  // namespace

void readSettings(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    sandbox::SessionOptions options;
    std::string block;
    for (std::size_t start = 0; start < text.size();) {
        const std::size_t end = std::min(text.find('\n', start), text.size());
        const std::string line = text.substr(start, end - start);
        if (!line.empty() && line[0] == '{') {
            block = text.substr(start);
            break;
        }
        start = end + 1;
        if (line.rfind("--mode ", 0) == 0) options.options.emplace_back("mode=" + line.substr(7), "--mode");
        else if (line.rfind("--quality ", 0) == 0) options.options.emplace_back("quality=" + line.substr(10), "--quality");
        else options.settings.push_back(line);
    }
    try {
        static const std::vector<unsigned char> asIs = [] {
            std::ifstream in(kScene, std::ios::binary);
            return std::vector<unsigned char>(std::istreambuf_iterator<char>(in), {});
        }();
        std::vector<unsigned char> bytes;
        if (block.empty()) {
            bytes = asIs;
        } else {
            const nlohmann::json parsed = nlohmann::json::parse(block, nullptr, false);
            if (parsed.is_discarded()) return;  // not JSON: the scene's loader would refuse the file
            bytes = sceneWithRenderBlock(parsed);
        }
        auto scene = std::make_shared<const assets::Scene>(assets::loadSceneFromMemory(std::move(bytes), kScene));
        options.defaultQuality = "balanced";  // as sandbox render
        sandbox::Session session(scene, options);
    } catch (const InputError&) {
        // Refused with its one-line reason.
    }
}

}  // namespace nimbus::fuzz
