#pragma once
// Undo and redo for the editor: every edit is one step holding the document's JSON before and
// after it, and the selection on each side. Documents are small, so whole snapshots keep every
// edit (add and delete included) trivially reversible.
//
// Does not: merge steps (a gizmo drag is committed once, on release) or limit memory.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace nimbus::sandbox::editor {

struct HistoryStep {
    std::string label;  // "set medium.extinction", "add emitter 'puff'"
    nlohmann::json before, after;
    int selectionBefore = -1, selectionAfter = -1;
};

class History {
public:
    void push(HistoryStep step);  // drops the steps that were undone
    const HistoryStep* undo();    // the step to revert, or nullptr
    const HistoryStep* redo();    // the step to apply again, or nullptr
    const HistoryStep& peekUndo() const { return steps_[position_ - 1]; }  // needs canUndo()
    const HistoryStep& peekRedo() const { return steps_[position_]; }      // needs canRedo()
    bool canUndo() const { return position_ > 0; }
    bool canRedo() const { return position_ < steps_.size(); }
    std::string undoLabel() const { return canUndo() ? steps_[position_ - 1].label : ""; }
    std::string redoLabel() const { return canRedo() ? steps_[position_].label : ""; }
    // Saving marks the current position; the document is clean while the position is there.
    void markSaved() { saved_ = position_; }
    bool atSaved() const { return saved_ == position_; }
    void clear() { steps_.clear(); position_ = 0; saved_ = 0; }

private:
    std::vector<HistoryStep> steps_;
    std::size_t position_ = 0;
    std::size_t saved_ = 0;  // SIZE_MAX once the saved state was dropped by a new edit
};

}  // namespace nimbus::sandbox::editor
