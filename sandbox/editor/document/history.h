#pragma once
// Undo and redo for the editor: every edit is one step from one state of the document's JSON to the
// next, with the selection on each side. Whole states keep every edit (add and delete included)
// trivially reversible. A state is held as compact JSON text, a fraction of the parsed tree's size,
// and a step's "after" is the next step's "before", held once.
//
// The history holds at most limitBytes() of states (256 MiB unless told otherwise). Past it, the
// oldest steps are dropped, newest kept, and push() returns how many went, so the editor can say so.
// One step larger than the whole limit is still kept, alone.
//
// Does not: merge steps (a gizmo drag is committed once, on release), or compress the states.
#include <cstddef>
#include <deque>
#include <memory>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

namespace nimbus::sandbox::editor {

struct HistoryStep {
    std::string label;  // "set medium.extinction", "add emitter 'puff'"
    nlohmann::json before, after;
    int selectionBefore = -1, selectionAfter = -1;
};

// Where undo or redo leads: the document's JSON and the selection there.
struct HistoryState {
    nlohmann::json json;
    int selection = -1;
};

class History {
public:
    static constexpr std::size_t kDefaultLimitBytes = std::size_t{256} << 20;

    explicit History(std::size_t limitBytes = kDefaultLimitBytes) : limit_(limitBytes) {}

    // Drops the steps that were undone, then the oldest steps while over the limit. Returns how
    // many of the oldest steps it dropped.
    std::size_t push(const HistoryStep& step);
    // The state undo or redo would lead to (parsed), or nullopt when there is none.
    std::optional<HistoryState> peekUndo() const;
    std::optional<HistoryState> peekRedo() const;
    void undo();  // needs canUndo()
    void redo();  // needs canRedo()
    bool canUndo() const { return position_ > 0; }
    bool canRedo() const { return position_ < steps_.size(); }
    std::string undoLabel() const { return canUndo() ? steps_[position_ - 1].label : ""; }
    std::string redoLabel() const { return canRedo() ? steps_[position_].label : ""; }
    // Saving marks the current position; the document is clean while the position is there.
    void markSaved() { saved_ = position_; }
    bool atSaved() const { return saved_ == position_; }
    void clear();

    std::size_t size() const { return steps_.size(); }
    std::size_t bytes() const { return bytes_; }            // what the kept steps hold, labels and states
    std::size_t limitBytes() const { return limit_; }
    std::size_t droppedSinceClear() const { return dropped_; }  // oldest steps dropped since clear()

private:
    using Text = std::shared_ptr<const std::string>;
    struct Stored {
        std::string label;
        Text before, after;
        int selectionBefore = -1, selectionAfter = -1;
    };
    Text keep(const nlohmann::json& state, const Text& same);
    void release(Stored& step);
    std::size_t dropOldest();

    std::deque<Stored> steps_;
    std::size_t position_ = 0;
    std::size_t saved_ = 0;  // kNotReachable once the saved state was dropped or overwritten
    std::size_t bytes_ = 0;
    std::size_t limit_;
    std::size_t dropped_ = 0;
};

}  // namespace nimbus::sandbox::editor
