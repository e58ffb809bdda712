#include "document/history.h"

#include <gtest/gtest.h>

namespace nimbus::sandbox::editor {
namespace {

using Json = nlohmann::json;

HistoryStep step(int before, int after) { return {"step", before, after, -1, -1}; }

// A document state of about `bytes` characters of JSON, told apart by `id`.
Json document(int id, std::size_t bytes) { return {{"id", id}, {"padding", std::string(bytes, 'x')}}; }

HistoryStep edit(int id, std::size_t bytes) {
    return {"edit " + std::to_string(id), document(id, bytes), document(id + 1, bytes), id, id + 1};
}

TEST(History, UndoRedoWalkTheSteps) {
    History h;
    EXPECT_FALSE(h.canUndo());
    EXPECT_FALSE(h.peekUndo());
    h.push(step(0, 1));
    h.push(step(1, 2));
    ASSERT_TRUE(h.canUndo());
    EXPECT_EQ(h.peekUndo()->json, 1);
    h.undo();
    EXPECT_EQ(h.peekUndo()->json, 0);
    h.undo();
    EXPECT_FALSE(h.canUndo());
    EXPECT_EQ(h.peekRedo()->json, 1);
    h.redo();
    h.push(step(1, 5));  // a new edit drops what was undone
    EXPECT_FALSE(h.canRedo());
    EXPECT_EQ(h.size(), 2u);
    h.undo();
    EXPECT_EQ(h.peekRedo()->json, 5);
}

TEST(History, StatesComeBackAsTheyWentIn) {
    History h;
    const Json before = {{"nodes", {{{"name", "a"}, {"translation", {0.1, -2.5e-17, 3.0}}}}}, {"asset", {{"version", "2.0"}}}};
    const Json after = {{"nodes", {{{"name", "b"}, {"scale", {1, 2, 3}}}}}, {"u", 18446744073709551615u}};
    h.push({"rename", before, after, 3, 4});
    EXPECT_EQ(h.peekUndo()->json, before);
    EXPECT_EQ(h.peekUndo()->selection, 3);
    h.undo();
    EXPECT_EQ(h.peekRedo()->json, after);
    EXPECT_EQ(h.peekRedo()->selection, 4);
}

TEST(History, SavedPositionMakesTheDocumentClean) {
    History h;
    EXPECT_TRUE(h.atSaved());
    h.push(step(0, 1));
    EXPECT_FALSE(h.atSaved());
    h.markSaved();
    EXPECT_TRUE(h.atSaved());
    h.undo();
    EXPECT_FALSE(h.atSaved());
    h.redo();
    EXPECT_TRUE(h.atSaved());
    h.undo();
    h.push(step(0, 7));  // the saved state can no longer be reached
    EXPECT_FALSE(h.atSaved());
    h.undo();
    EXPECT_FALSE(h.atSaved());
}

// A step's "after" is the next step's "before": a chain of n steps holds n + 1 states, not 2n.
TEST(History, AdjacentStatesAreHeldOnce) {
    History one, chain;
    one.push(edit(0, 10000));
    for (int i = 0; i < 4; ++i) chain.push(edit(i, 10000));
    const std::size_t perState = one.bytes() / 2;
    EXPECT_GT(perState, 10000u);
    EXPECT_LT(chain.bytes(), 5 * perState + 5 * 200);
    EXPECT_GT(chain.bytes(), 5 * perState - 5 * 200);
}

TEST(History, UndoneStepsLetGoOfTheirBytes) {
    History walked, fresh;
    for (int i = 0; i < 3; ++i) walked.push(edit(i, 5000));
    walked.undo();
    walked.undo();
    walked.push(edit(1, 5000));
    fresh.push(edit(0, 5000));
    fresh.push(edit(1, 5000));
    EXPECT_EQ(walked.bytes(), fresh.bytes());
    walked.clear();
    EXPECT_EQ(walked.bytes(), 0u);
}

TEST(History, OverTheLimitTheOldestStepsAreDroppedAndSaid) {
    const std::size_t limit = 64 * 1024, stateBytes = 4000;
    History h(limit);
    std::size_t dropped = 0, firstDrop = 0;
    for (int i = 0; i < 100; ++i) {
        const std::size_t now = h.push(edit(i, stateBytes));
        if (now > 0 && firstDrop == 0) firstDrop = static_cast<std::size_t>(i);
        dropped += now;
        EXPECT_LE(h.bytes(), limit);
    }
    ASSERT_GT(firstDrop, 0u);
    EXPECT_EQ(dropped, h.droppedSinceClear());
    EXPECT_EQ(dropped + h.size(), 100u);
    EXPECT_GT(h.bytes(), limit - 2 * (stateBytes + 300));  // full, give or take one state
    // Undo walks back through every kept step to the oldest kept state, then stops.
    std::size_t undone = 0;
    while (h.canUndo()) {
        h.undo();
        ++undone;
    }
    EXPECT_EQ(undone, h.size());
    EXPECT_EQ(h.peekRedo()->json, document(static_cast<int>(dropped) + 1, stateBytes));
    EXPECT_EQ(h.peekRedo()->selection, static_cast<int>(dropped) + 1);
    h.clear();
    EXPECT_EQ(h.droppedSinceClear(), 0u);
}

TEST(History, ASavedStateThatWasDroppedIsNeverCleanAgain) {
    History h(20 * 1024);
    h.push(edit(0, 4000));
    h.undo();
    h.markSaved();  // saved at the very first state
    h.redo();
    for (int i = 1; i < 10; ++i) h.push(edit(i, 4000));
    ASSERT_GT(h.droppedSinceClear(), 0u);
    while (h.canUndo()) {
        EXPECT_FALSE(h.atSaved());
        h.undo();
    }
    EXPECT_FALSE(h.atSaved());
}

TEST(History, AStepLargerThanTheLimitIsKeptAlone) {
    History h(1024);
    h.push(edit(0, 100));
    EXPECT_EQ(h.push(edit(1, 5000)), 1u);
    EXPECT_EQ(h.size(), 1u);
    ASSERT_TRUE(h.canUndo());
    EXPECT_EQ(h.peekUndo()->json, document(1, 5000));
}

}  // namespace
}  // namespace nimbus::sandbox::editor
