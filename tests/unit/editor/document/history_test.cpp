#include "document/history.h"

#include <gtest/gtest.h>

namespace nimbus::sandbox::editor {
namespace {

HistoryStep step(int before, int after) { return {"step", before, after, -1, -1}; }

TEST(History, UndoRedoWalkTheSteps) {
    History h;
    EXPECT_FALSE(h.canUndo());
    h.push(step(0, 1));
    h.push(step(1, 2));
    ASSERT_TRUE(h.canUndo());
    EXPECT_EQ(h.undo()->before, 1);
    EXPECT_EQ(h.undo()->before, 0);
    EXPECT_EQ(h.undo(), nullptr);
    EXPECT_EQ(h.redo()->after, 1);
    h.push(step(1, 5));  // a new edit drops what was undone
    EXPECT_FALSE(h.canRedo());
    EXPECT_EQ(h.undo()->after, 5);
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

}  // namespace
}  // namespace nimbus::sandbox::editor
