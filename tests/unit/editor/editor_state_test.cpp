#include "editor_state.h"

#include <gtest/gtest.h>

#include "nimbus/base/error.h"
#include "nimbus/media/ecs/media_plugin.h"

namespace nimbus::sandbox::editor {
namespace {

namespace fs = std::filesystem;
const fs::path kContent = NIMBUS_CONTENT_DIR_FOR_TESTS;
const fs::path kData = NIMBUS_TEST_DATA_DIR;
const std::string kMedium = "extensions.NIMBUS_participating_media.medium.";

struct Refusal {
    std::string path;
    Json value;
    std::string says;  // part of the loader's message
};

class EditorStateTest : public ::testing::Test {
protected:
    void SetUp() override {
        state.open(kContent / "scenes/smoke.gltf");
        state.selectByName("chimney");
    }
    EditorState state;
};

TEST_F(EditorStateTest, InvalidValuesAreRefusedWithTheLoadersMessageAndChangeNothing) {
    const Refusal refusals[] = {
        {kMedium + "extinction", -1.0, "extinction: must be > 0"},
        {kMedium + "g", 1.0, "g"},
        {"extensions.NIMBUS_participating_media.emitter.preset", "drizzle", "preset"},
    };
    const Json before = state.json();
    const auto revision = state.revision();
    for (const Refusal& r : refusals) {
        try {
            state.setOnSelected(r.path, r.value);
            ADD_FAILURE() << r.path << " = " << r.value << " was accepted";
        } catch (const InputError& e) {
            const std::string message = e.what();
            EXPECT_NE(message.find("smoke.gltf"), std::string::npos) << message;
            EXPECT_NE(message.find("chimney"), std::string::npos) << message;
            EXPECT_NE(message.find(r.says), std::string::npos) << message;
        }
        EXPECT_EQ(state.json(), before);
        EXPECT_EQ(state.revision(), revision);
        EXPECT_FALSE(state.history().canUndo());
        EXPECT_FALSE(state.dirty());
    }
}

TEST_F(EditorStateTest, TheOpticalModelTogglesAsOneUndoableEditAndReachesTheSession) {
    const std::string field = "extensions.NIMBUS_participating_media.scattering";
    ASSERT_EQ(state.session().scene().environment.scattering, assets::Scattering::Multiple);  // the default
    state.set({{-1, field, "single"}}, "scattering");
    EXPECT_EQ(state.session().scene().environment.scattering, assets::Scattering::Single);
    EXPECT_EQ(getField(state.json(), -1, field), "single");
    EXPECT_THROW(state.set({{-1, field, "double"}}, "scattering"), InputError);  // the loader's refusal
    EXPECT_EQ(state.session().scene().environment.scattering, assets::Scattering::Single);
    ASSERT_TRUE(state.undo());
    EXPECT_EQ(state.session().scene().environment.scattering, assets::Scattering::Multiple);
}

TEST_F(EditorStateTest, AddUndoRedoRestoreDocumentAndSelection) {
    const Json original = state.json();
    const int added = state.add(NodeKind::Emitter, "puff", glm::dvec3(1.0, 0.0, 0.0), "steam");
    EXPECT_EQ(state.selected(), added);
    EXPECT_EQ(getField(state.json(), added, "extensions.NIMBUS_participating_media.emitter.preset"), "steam");
    EXPECT_TRUE(state.dirty());
    ASSERT_TRUE(state.undo());
    EXPECT_EQ(state.json(), original);
    EXPECT_EQ(state.selected(), findNode(original, "chimney"));
    ASSERT_TRUE(state.redo());
    EXPECT_EQ(state.selected(), added);
    state.removeSelected();
    EXPECT_EQ(findNode(state.json(), "puff"), -1);
    ASSERT_TRUE(state.undo());
    EXPECT_EQ(findNode(state.json(), "puff"), added);
}

std::vector<glm::dvec3> particlePositions(Session& session) {
    media::ParticleSet particles;
    media::ecs::gatherParticles(session.app().world(), particles);
    return particles.position;
}

TEST_F(EditorStateTest, ScrubbingAndPlayingReachTheSameState) {
    for (int i = 0; i < 45; ++i) state.advance(1.0 / 30.0);
    const auto played = particlePositions(state.session());
    ASSERT_FALSE(played.empty());
    state.scrub(0.0);
    state.scrub(1.5);
    EXPECT_EQ(particlePositions(state.session()), played);
}

TEST_F(EditorStateTest, AFailedOpenKeepsTheScene) {
    const Json before = state.json();
    EXPECT_THROW(state.open(kData / "malformed/accessor_out_of_range.gltf"), InputError);
    EXPECT_EQ(state.json(), before);
    EXPECT_EQ(state.document().path(), kContent / "scenes/smoke.gltf");
}

TEST_F(EditorStateTest, BadViewSettingsAreRefused) {
    EXPECT_THROW(state.setQuality("ultra"), InputError);
    EXPECT_THROW(state.setMode("voxels"), InputError);
    EXPECT_EQ(state.view().quality, "");
    state.setMode("blocks");
    EXPECT_EQ(state.view().mode, "blocks");
}

// A long session under a small history limit: the history stays within it, says what it dropped,
// and undo still walks back through every kept edit to the oldest kept state.
TEST(EditorStateHistory, ALongSessionKeepsTheHistoryWithinItsLimit) {
    constexpr std::size_t kLimit = 48 * 1024;
    EditorState state({}, kLimit);
    state.open(kContent / "scenes/smoke.gltf");
    state.selectByName("chimney");
    const auto translationAfter = [](int edit) { return Json::array({0.25 * edit, 0.0, 0.0}); };
    constexpr int kEdits = 40;
    std::optional<std::string> firstNotice;
    for (int i = 1; i <= kEdits; ++i) {
        state.setOnSelected("translation", translationAfter(i));
        EXPECT_LE(state.history().bytes(), kLimit);
        if (auto notice = state.takeNotice(); notice && !firstNotice) firstNotice = notice;
    }
    ASSERT_TRUE(firstNotice) << "the history never reached its limit";
    EXPECT_NE(firstNotice->find("undo history at its 48 KiB limit: dropped the oldest 1 step"), std::string::npos) << *firstNotice;
    const History& h = state.history();
    ASSERT_GT(h.droppedSinceClear(), 0u);
    EXPECT_EQ(h.droppedSinceClear() + h.size(), static_cast<std::size_t>(kEdits));
    const int chimney = findNode(state.json(), "chimney");
    int undone = 0;
    while (state.undo()) ++undone;
    EXPECT_EQ(undone, static_cast<int>(h.size()));
    EXPECT_EQ(getField(state.json(), chimney, "translation"), translationAfter(static_cast<int>(h.droppedSinceClear())));
    EXPECT_TRUE(state.dirty());  // the file's own state was dropped: nothing here is what is on disk
    EXPECT_EQ(state.selected(), chimney);
}

}  // namespace
}  // namespace nimbus::sandbox::editor
