// Every file of each fuzz target's seed and regression corpora (tests/fuzz/corpus/<target>/ and
// tests/fuzz/regressions/<target>/) replayed through the target's entry in this build: an input
// that once crashed stays fixed in the release build too, sanitizers or not.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <vector>

#include "fuzz_entries.h"
#include "nimbus/base/log.h"

// tests/lsan.supp's suppressions, compiled in: gtest_discover_tests hands a test a single
// environment variable intact (ASAN_OPTIONS here), so LSAN_OPTIONS cannot name the file.
extern "C" const char* __lsan_default_suppressions() { return "leak:OpenImageIO_v2_4::ImageInput::geterror\n"; }

namespace nimbus::fuzz {
namespace {

namespace fs = std::filesystem;
using Entry = std::function<void(const std::uint8_t*, std::size_t)>;

std::vector<fs::path> filesOf(const std::string& target) {
    std::vector<fs::path> files;
    for (const char* corpus : {"corpus", "regressions"}) {
        const fs::path dir = fs::path(NIMBUS_FUZZ_DIR) / corpus / target;
        if (!fs::is_directory(dir)) continue;
        for (const auto& entry : fs::directory_iterator(dir))
            if (entry.is_regular_file() && entry.path().filename() != "README.md") files.push_back(entry.path());
    }
    std::sort(files.begin(), files.end());
    return files;
}

void replay(const std::string& target, const Entry& entry, std::size_t atLeast) {
    const log::Level level = log::level();
    log::setLevel(log::Level::Off);
    const std::vector<fs::path> files = filesOf(target);
    EXPECT_GE(files.size(), atLeast) << "the " << target << " corpus is missing";
    for (const fs::path& file : files) {
        SCOPED_TRACE(file.string());
        std::ifstream in(file, std::ios::binary);
        const std::vector<std::uint8_t> bytes{std::istreambuf_iterator<char>(in), {}};
        EXPECT_NO_THROW(entry(bytes.data(), bytes.size()));
    }
    log::setLevel(level);
}

TEST(FuzzCorpus, SceneFilesAreLoadedOrRefused) { replay("scene", &loadScene, 20); }
TEST(FuzzCorpus, EditorScriptsRunOrStopAtARefusedLine) { replay("editor_script", &runEditorScript, 5); }
TEST(FuzzCorpus, SettingsAreReadOrRefused) { replay("settings", &readSettings, 5); }

}  // namespace
}  // namespace nimbus::fuzz
