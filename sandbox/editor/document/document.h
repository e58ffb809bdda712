#pragma once
// The file being edited: its glTF JSON and GLB BIN chunk exactly as read, and where it lives.
// Saving writes what the JSON says, so what Nimbus does not edit (other extensions, extras,
// unknown nodes) goes back as it came, and a saved file loads to the same JSON and bytes.
//
// Does not: check the content (load() runs the loader's checks), or keep an edit history.
#include <filesystem>
#include <vector>

#include "nimbus/assets/gltf_file.h"
#include "nimbus/assets/scene.h"

namespace nimbus::sandbox::editor {

class Document {
public:
    // An empty scene, not yet saved anywhere.
    static Document empty();
    // Reads the file and loads it once, so a malformed file is refused with the loader's message.
    static Document open(const std::filesystem::path& file);

    const std::filesystem::path& path() const { return path_; }  // empty while untitled
    bool isUntitled() const { return path_.empty(); }
    nlohmann::json& json() { return file_.json; }
    const nlohmann::json& json() const { return file_.json; }
    const std::vector<unsigned char>& binChunk() const { return file_.binChunk; }

    // The scene the document describes, with every check of loadScene (InputError naming the file).
    assets::Scene load() const;

    // Writes to `target`: .gltf as JSON text (a GLB's BIN chunk becomes STEM.bin beside it), .glb as
    // one container (buffer 0 embedded). Files the document references by relative URI are copied
    // when the folder changes. The document then lives at `target`.
    void saveAs(const std::filesystem::path& target);

private:
    std::filesystem::path directory() const;

    std::filesystem::path path_;
    assets::GltfFile file_;
};

}  // namespace nimbus::sandbox::editor
