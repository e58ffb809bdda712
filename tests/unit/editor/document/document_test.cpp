#include "document/document.h"

#include <gtest/gtest.h>

#include <fstream>

#include "nimbus/base/error.h"

namespace nimbus::sandbox::editor {
namespace {

namespace fs = std::filesystem;

const fs::path kData = NIMBUS_TEST_DATA_DIR;
const fs::path kContent = NIMBUS_CONTENT_DIR_FOR_TESTS;

fs::path tempFolder(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("nimbus_document_test_" + name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

std::vector<char> bytesOf(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(Document, SavedGltfLoadsToTheSameJsonAndBytes) {
    const fs::path dir = tempFolder("gltf");
    Document doc = Document::open(kContent / "scenes/smoke.gltf");
    const nlohmann::json original = doc.json();
    doc.saveAs(dir / "copy.gltf");
    EXPECT_EQ(doc.path(), dir / "copy.gltf");
    const Document again = Document::open(dir / "copy.gltf");
    EXPECT_EQ(again.json(), original);
    EXPECT_EQ(bytesOf(dir / "smoke.bin"), bytesOf(kContent / "scenes/smoke.bin"));  // referenced files come along
}

TEST(Document, GltfToGlbEmbedsBufferZeroAndBack) {
    const fs::path dir = tempFolder("glb");
    Document doc = Document::open(kContent / "scenes/smoke.gltf");
    doc.saveAs(dir / "scene.glb");
    const Document glb = Document::open(dir / "scene.glb");
    EXPECT_FALSE(glb.json()["buffers"][0].contains("uri"));
    const auto original = bytesOf(kContent / "scenes/smoke.bin");
    ASSERT_EQ(glb.binChunk().size(), (original.size() + 3) / 4 * 4);
    EXPECT_TRUE(std::equal(original.begin(), original.end(), reinterpret_cast<const char*>(glb.binChunk().data())));
    Document back = glb;
    back.saveAs(dir / "back.gltf");  // the BIN chunk becomes back.bin beside it
    EXPECT_EQ(Document::open(dir / "back.gltf").json()["buffers"][0]["uri"], "back.bin");
    EXPECT_NO_THROW((void)Document::open(dir / "back.gltf").load());
}

TEST(Document, KeepsWhatNimbusDoesNotEdit) {
    const fs::path dir = tempFolder("unknown");
    Document doc = Document::open(kContent / "scenes/smoke.gltf");
    doc.json()["extras"] = {{"studio", {{"owner", "fx"}, {"ticket", 42}}}};
    doc.json()["nodes"][0]["extras"] = {{"lod", 2}};
    doc.saveAs(dir / "extras.gltf");
    const Document again = Document::open(dir / "extras.gltf");
    EXPECT_EQ(again.json()["extras"]["studio"]["ticket"], 42);
    EXPECT_EQ(again.json()["nodes"][0]["extras"]["lod"], 2);
}

TEST(Document, MalformedFileIsRefusedWithTheLoadersMessage) {
    try {
        (void)Document::open(kData / "malformed/accessor_out_of_range.gltf");
        FAIL() << "opened a malformed file";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("accessor_out_of_range.gltf"), std::string::npos) << e.what();
    }
}

TEST(Document, SaveNeedsAGltfOrGlbName) {
    Document doc = Document::open(kContent / "scenes/smoke.gltf");
    EXPECT_THROW(doc.saveAs(tempFolder("name") / "scene.txt"), InputError);
    EXPECT_EQ(doc.path(), kContent / "scenes/smoke.gltf");
}

TEST(Document, EmptyDocumentLoads) {
    const Document doc = Document::empty();
    EXPECT_TRUE(doc.isUntitled());
    EXPECT_NO_THROW((void)doc.load());
}

}  // namespace
}  // namespace nimbus::sandbox::editor
