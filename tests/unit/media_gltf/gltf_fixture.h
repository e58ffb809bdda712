#pragma once
// Test helper: writes small glTF files (JSON + one .bin buffer) into a fresh temporary folder, so
// tests can exercise the real loader with exactly the data they need.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace nimbus::media::test {

class GltfFixture {
public:
    GltfFixture() {
        root_ = {{"asset", {{"version", "2.0"}}}, {"scene", 0}, {"scenes", {{{"nodes", nlohmann::json::array()}}}},
                 {"nodes", nlohmann::json::array()}, {"extensionsUsed", {"NIMBUS_participating_media"}}};
    }

    nlohmann::json& root() { return root_; }

    // A FLOAT accessor; type "SCALAR", "VEC2" or "VEC3". Returns its index.
    int addFloats(const std::vector<float>& values, const std::string& type) {
        const int components = type == "SCALAR" ? 1 : type == "VEC2" ? 2 : 3;
        const int view = addView(values.data(), values.size() * sizeof(float));
        nlohmann::json accessor = {{"bufferView", view}, {"componentType", 5126},
                                   {"count", values.size() / static_cast<std::size_t>(components)}, {"type", type}};
        if (type == "VEC3" && !values.empty()) {  // POSITION needs bounds; harmless elsewhere
            std::vector<float> lo(values.begin(), values.begin() + 3), hi = lo;
            for (std::size_t i = 0; i < values.size(); ++i) {
                lo[i % 3] = std::min(lo[i % 3], values[i]);
                hi[i % 3] = std::max(hi[i % 3], values[i]);
            }
            accessor["min"] = lo;
            accessor["max"] = hi;
        }
        root_["accessors"].push_back(accessor);
        return static_cast<int>(root_["accessors"].size()) - 1;
    }

    int addIndices(const std::vector<std::uint32_t>& indices) {
        const int view = addView(indices.data(), indices.size() * sizeof(std::uint32_t));
        root_["accessors"].push_back({{"bufferView", view}, {"componentType", 5125}, {"count", indices.size()}, {"type", "SCALAR"}});
        return static_cast<int>(root_["accessors"].size()) - 1;
    }

    // Adds a node to the default scene (as a root) and returns its index.
    int addNode(const nlohmann::json& node) {
        root_["nodes"].push_back(node);
        const int index = static_cast<int>(root_["nodes"].size()) - 1;
        root_["scenes"][0]["nodes"].push_back(index);
        return index;
    }

    // A particle node: positions (xyz...), radii, optional densities, the given medium object.
    int addCloud(const std::string& name, const std::vector<float>& positions, const std::vector<float>& radii,
                 const nlohmann::json& medium, const std::vector<float>& densities = {},
                 const nlohmann::json& extra = nlohmann::json::object()) {
        nlohmann::json particles = {{"position", addFloats(positions, "VEC3")}, {"radius", addFloats(radii, "SCALAR")}};
        if (!densities.empty()) particles["density"] = addFloats(densities, "SCALAR");
        nlohmann::json ext = {{"medium", medium}, {"particles", particles}};
        for (auto it = extra.begin(); it != extra.end(); ++it) ext[it.key()] = it.value();
        nlohmann::json node = {{"name", name}, {"extensions", {{"NIMBUS_participating_media", ext}}}};
        return addNode(node);
    }

    // Writes name.gltf + name.bin into a fresh folder; returns the .gltf path.
    std::filesystem::path write(const std::string& name) {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        const std::filesystem::path dir = std::filesystem::temp_directory_path() / "nimbus_tests" /
                                          (std::string(info->test_suite_name()) + "." + info->name());
        std::filesystem::create_directories(dir);
        nlohmann::json out = root_;
        if (!bytes_.empty()) out["buffers"] = {{{"byteLength", bytes_.size()}, {"uri", name + ".bin"}}};
        std::ofstream(dir / (name + ".bin"), std::ios::binary).write(reinterpret_cast<const char*>(bytes_.data()),
                                                                    static_cast<std::streamsize>(bytes_.size()));
        std::ofstream(dir / (name + ".gltf")) << out.dump(1);
        return dir / (name + ".gltf");
    }

private:
    int addView(const void* data, std::size_t size) {
        while (bytes_.size() % 4 != 0) bytes_.push_back(0);
        const std::size_t offset = bytes_.size();
        bytes_.resize(offset + size);
        std::memcpy(bytes_.data() + offset, data, size);
        root_["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", size}});
        return static_cast<int>(root_["bufferViews"].size()) - 1;
    }

    nlohmann::json root_;
    std::vector<std::uint8_t> bytes_;
};

}  // namespace nimbus::media::test
