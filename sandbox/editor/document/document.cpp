#include "document.h"

#include <algorithm>
#include <cctype>
#include <fstream>

#include "nimbus/base/error.h"

namespace nimbus::sandbox::editor {
namespace {

bool endsWithGlb(const std::filesystem::path& file) {
    std::string ext = file.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (ext != ".glb" && ext != ".gltf")
        throwInputError(file.string(), "save", "file name", "must end in .gltf or .glb");
    return ext == ".glb";
}

std::vector<unsigned char> readBytes(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throwInputError(file.string(), "", "", "cannot read the file");
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Writes through a temporary file and a rename, so a failed save never leaves half a file.
void writeBytes(const std::filesystem::path& file, const std::vector<unsigned char>& bytes) {
    const std::filesystem::path temp = file.string() + ".saving";
    {
        std::ofstream out(temp, std::ios::binary | std::ios::trunc);
        if (!out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size())))
            throwInputError(file.string(), "", "", "cannot write the file");
    }
    std::error_code ec;
    std::filesystem::rename(temp, file, ec);
    if (ec) throwInputError(file.string(), "", "", "cannot write the file: " + ec.message());
}

// A file name that needs no percent-encoding as a URI.
std::string safeFileName(const std::string& stem) {
    std::string out = stem;
    for (char& c : out)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_' && c != '.') c = '_';
    return out.empty() ? "buffer" : out;
}

bool hasFileUri(const nlohmann::json& buffer) {
    return buffer.contains("uri") && buffer["uri"].is_string() &&
           buffer["uri"].get<std::string>().rfind("data:", 0) != 0;
}

void copyReferencedFiles(const nlohmann::json& json, const std::filesystem::path& from, const std::filesystem::path& to) {
    std::error_code ec;
    if (std::filesystem::equivalent(from, to, ec)) return;
    for (const std::string& uri : assets::fileUris(json)) {
        const auto source = assets::resolveFileUri(from, uri), target = assets::resolveFileUri(to, uri);
        std::filesystem::create_directories(target.parent_path(), ec);
        if (!std::filesystem::copy_file(source, target, std::filesystem::copy_options::overwrite_existing, ec))
            throwInputError(target.string(), "", "", "cannot copy " + source.string() + ": " + ec.message());
    }
}

}  // namespace

Document Document::empty() {
    Document doc;
    doc.file_.json = {{"asset", {{"version", "2.0"}, {"generator", "Nimbus sandbox edit"}}},
                      {"scene", 0},
                      {"scenes", nlohmann::json::array({nlohmann::json::object()})}};
    return doc;
}

Document Document::open(const std::filesystem::path& file) {
    Document doc;
    doc.file_ = assets::readGltfFile(file);
    doc.path_ = file;
    (void)doc.load();
    return doc;
}

std::filesystem::path Document::directory() const {
    std::error_code ec;
    const auto absolute = std::filesystem::absolute(isUntitled() ? std::filesystem::path("untitled.gltf") : path_, ec);
    return absolute.parent_path();
}

assets::Scene Document::load() const {
    const std::filesystem::path name = isUntitled() ? std::filesystem::path("untitled.gltf") : path_;
    return assets::loadSceneFromMemory(assets::encodeGltf(file_.json, file_.binChunk, file_.binary), name);
}

void Document::saveAs(const std::filesystem::path& target) {
    const bool binary = endsWithGlb(target);
    std::error_code ec;
    const std::filesystem::path folder = std::filesystem::absolute(target, ec).parent_path();
    nlohmann::json json = file_.json;
    std::vector<unsigned char> bin = file_.binChunk;
    copyReferencedFiles(json, directory(), folder);
    if (binary && bin.empty() && json.contains("buffers") && !json["buffers"].empty() && hasFileUri(json["buffers"][0])) {
        bin = readBytes(assets::resolveFileUri(directory(), json["buffers"][0]["uri"].get<std::string>()));
        bin.resize(json["buffers"][0].value("byteLength", bin.size()));  // GLB: the chunk holds exactly the buffer
        json["buffers"][0].erase("uri");
    }
    if (!binary && !bin.empty()) {
        const std::string name = safeFileName(target.stem().string()) + ".bin";
        writeBytes(folder / name, bin);
        json["buffers"][0]["uri"] = name;
        bin.clear();
    }
    writeBytes(target, assets::encodeGltf(json, bin, binary));
    file_ = {std::move(json), std::move(bin), binary};
    path_ = target;
}

}  // namespace nimbus::sandbox::editor
