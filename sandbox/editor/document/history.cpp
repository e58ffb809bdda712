#include "history.h"

namespace nimbus::sandbox::editor {

void History::push(HistoryStep step) {
    steps_.resize(position_);
    if (saved_ > position_) saved_ = static_cast<std::size_t>(-1);  // the saved state can no longer be reached
    steps_.push_back(std::move(step));
    position_ = steps_.size();
}

const HistoryStep* History::undo() {
    if (!canUndo()) return nullptr;
    return &steps_[--position_];
}

const HistoryStep* History::redo() {
    if (!canRedo()) return nullptr;
    return &steps_[position_++];
}

}  // namespace nimbus::sandbox::editor
