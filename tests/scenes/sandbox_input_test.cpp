// Every input a user can type, as the issue lists them: each either works or is refused with one
// line that starts "sandbox:" (or "sandbox edit:") and exit code 2, before any long work starts.
// A run that hangs is killed at kLimitSeconds and fails.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include "process.h"

namespace nimbus::test {
namespace {

namespace fs = std::filesystem;

const fs::path kData = NIMBUS_TEST_DATA_DIR;
const fs::path kContent = NIMBUS_CONTENT_DIR_FOR_TESTS;
constexpr double kLimitSeconds = 60.0;  // a hang's cap, far above any refusal

std::string joined(const std::vector<std::string>& args) {
    std::string out = "sandbox";
    for (const auto& a : args) out += " " + a;
    return out;
}


ProcessResult sandbox(const std::vector<std::string>& args) { return runProcess(sandboxExecutable(), args, kLimitSeconds); }

// Refused: exit 2, one line on stderr starting with the prefix and naming `mentions`, nothing on stdout.
void expectOneLineRefusal(const std::vector<std::string>& args, const std::vector<std::string>& mentions,
                          const std::string& prefix = "sandbox: ") {
    SCOPED_TRACE(joined(args));
    const ProcessResult r = sandbox(args);
    ASSERT_FALSE(r.timedOut) << "still running after " << kLimitSeconds << " s instead of refusing";
    EXPECT_FALSE(r.signaled) << explain(r);
    EXPECT_EQ(r.exitCode, 2) << explain(r);
    const std::vector<std::string> lines = r.errLines();
    ASSERT_EQ(lines.size(), 1u) << explain(r);
    EXPECT_EQ(lines[0].rfind(prefix, 0), 0u) << lines[0];
    EXPECT_LT(lines[0].size(), 400u) << "a readable line: " << lines[0];
    for (const std::string& m : mentions) EXPECT_NE(lines[0].find(m), std::string::npos) << m << " in: " << lines[0];
    EXPECT_TRUE(r.out.empty()) << r.out;
}

const std::string box() { return (kData / "khronos/Box/Box.gltf").string(); }
const std::string smoke() { return (kContent / "scenes/smoke.gltf").string(); }

TEST(SandboxInput, NotANumberTimeIsRefusedAtOnceByEveryCommand) {
    expectOneLineRefusal({"render", smoke(), "--time", "nan", "--size", "16x16"}, {"--time", "nan"});
    expectOneLineRefusal({"validate", smoke(), "--time", "nan"}, {"--time", "nan"});
    expectOneLineRefusal({"bench", smoke(), "--time", "nan"}, {"--time", "nan"});
    expectOneLineRefusal({"reference", smoke(), "--time", "nan", "--out", "/dev/null"}, {"--time", "nan"});
    expectOneLineRefusal({"render", smoke(), "--time", "inf", "--size", "16x16"}, {"--time"});
}

// docs/scene-format.md §4: more than 10^8 steps is refused before any work, with a short number.
TEST(SandboxInput, TimeBeyondTheStepLimitIsRefusedBeforeAnyWork) {
    expectOneLineRefusal({"reference", smoke(), "--time", "1e9", "--out", "/dev/null"}, {"--time", "100000000", "steps"});
    expectOneLineRefusal({"render", smoke(), "--time", "1e300", "--size", "16x16"}, {"--time", "1e+300"});
    expectOneLineRefusal({"validate", smoke(), "--time", "1" + std::string(300, '0')}, {"--time", "1e+300"});
    expectOneLineRefusal({"render", smoke(), "--time", "-1"}, {"--time", "-1"});
}

// A long simulation says so before it starts (and draws a progress bar on a terminal).
TEST(SandboxInput, LongSimulationAnnouncesItself) {
    TempFolder out;
    const std::vector<std::string> args = {"render", box(), "--time", "1000", "--size", "16x16", "--out", (out / "b.png").string()};
    SCOPED_TRACE(joined(args));
    const ProcessResult r = sandbox(args);
    ASSERT_EQ(r.exitCode, 0) << explain(r);
    EXPECT_NE(r.err.find("simulating 60000 steps"), std::string::npos) << explain(r);
    EXPECT_TRUE(fs::exists(out / "b.png"));
}

TEST(SandboxInput, ExposureMustBeAFinitePositiveNumber) {
    for (const char* e : {"nan", "inf", "0", "-1", "abc"})
        expectOneLineRefusal({"render", box(), "--size", "16x16", "--exposure", e, "--out", "/tmp/never.png"}, {"--exposure"});
}

// The parser's own errors are one line and exit 2 too, with the usage pointed to.
TEST(SandboxInput, ParserErrorsAreOneLine) {
    expectOneLineRefusal({"render", box(), "--bogus"}, {"--bogus", "--help"});
    expectOneLineRefusal({"render", box(), "--floor"}, {"--floor", "--stats"});
    expectOneLineRefusal({"render"}, {"scene"});
    expectOneLineRefusal({"frobnicate"}, {"frobnicate"});
    expectOneLineRefusal({"render", box(), "--size"}, {"--size"});
}

// A flag takes no value, and a boolean setting is on/off (or true/false): never "yes" or 1.
TEST(SandboxInput, BooleansAcceptOnlyTheirWords) {
    expectOneLineRefusal({"settings", "--schema=yes"}, {"--schema"});
    expectOneLineRefusal({"settings", "--schema=1"}, {"--schema"});
    expectOneLineRefusal({"render", box(), "--stats", "/dev/null", "--floor=yes"}, {"--floor"});
    expectOneLineRefusal({"render", box(), "--set", "soft_particles=yes", "--quality", "exact"}, {"soft_particles", "yes", "on or off"});
    expectOneLineRefusal({"render", box(), "--set", "layer_light=1", "--quality", "exact"}, {"layer_light", "on or off"});
}

TEST(SandboxInput, OutOfRangeSettingsAreRefusedNotClamped) {
    expectOneLineRefusal({"render", smoke(), "--mode", "blocks", "--set", "blocks=1000000"}, {"blocks", "1000000", "outside its range"});
    expectOneLineRefusal({"render", smoke(), "--set", "slices=" + std::string(300, '9')}, {"slices", "outside its range", "300 characters"});
    expectOneLineRefusal({"render", smoke(), "--set", "media_scale=1e300"}, {"media_scale", "outside its range"});
}

TEST(SandboxInput, AnOptionAndASetOfTheSameKeyMustAgree) {
    expectOneLineRefusal({"render", smoke(), "--quality", "fast", "--set", "quality=exact"}, {"--quality", "quality=exact"});
    expectOneLineRefusal({"render", smoke(), "--mode", "blocks", "--set", "mode=raymarch"}, {"--mode", "mode=raymarch"});
}

// A setting that would do nothing in the tier or mode is refused, saying so (the settings walk
// in tests/scenes/media/settings_walk_test.cpp covers every key).
TEST(SandboxInput, ASettingWithoutEffectIsRefused) {
    expectOneLineRefusal({"render", smoke(), "--set", "soft_particles=off"}, {"soft_particles", "no effect", "tier balanced"});
    expectOneLineRefusal({"render", smoke(), "--mode", "billboards", "--set", "slices=8"}, {"slices", "no effect", "mode billboards"});
}

TEST(SandboxInput, AScriptNeverRunsOnAnEmptyScene) {
    TempFolder dir;
    const fs::path script = dir / "s.txt";
    std::ofstream(script) << "select chimney\nsave " << (dir / "saved.gltf").string() << "\n";
    expectOneLineRefusal({"edit", (dir / "missing.gltf").string(), "--script", script.string()}, {"missing.gltf"});
    expectOneLineRefusal({"edit", smoke(), "--script", (dir / "no_script.txt").string()}, {"no_script.txt"});
    EXPECT_FALSE(fs::exists(dir / "saved.gltf"));
}

// Help texts list what the declarations accept: every mode and tier `sandbox settings` lists.
TEST(SandboxInput, HelpListsEveryDeclaredModeAndTier) {
    const ProcessResult settings = sandbox({"settings"});
    ASSERT_EQ(settings.exitCode, 0) << explain(settings);
    std::smatch m;
    ASSERT_TRUE(std::regex_search(settings.out, m, std::regex("\\n?mode +[^\\n]*; ([a-z_, ]+ or [a-z_]+); default"))) << settings.out;
    const std::string modes = m[1];
    for (const char* command : {"render", "edit"}) {
        const ProcessResult help = sandbox({command, "--help"});
        ASSERT_EQ(help.exitCode, 0) << explain(help);
        std::string flat;  // CLI11 wraps long descriptions
        for (char c : help.out) flat += (c == '\n' ? ' ' : c);
        flat = std::regex_replace(flat, std::regex(" +"), " ");
        EXPECT_NE(flat.find(modes), std::string::npos) << command << " --help lacks \"" << modes << "\":\n" << help.out;
        EXPECT_NE(flat.find("raymarch"), std::string::npos) << command << " --help:\n" << help.out;
        EXPECT_NE(flat.find("exact, balanced or fast"), std::string::npos) << command << " --help:\n" << help.out;
    }
}

}  // namespace
}  // namespace nimbus::test
