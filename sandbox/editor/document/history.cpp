#include "history.h"

namespace nimbus::sandbox::editor {
namespace {

constexpr std::size_t kNotReachable = static_cast<std::size_t>(-1);
// What a held state costs beyond its characters: the string and the shared pointer's control block.
constexpr std::size_t kStateOverhead = sizeof(std::string) + 4 * sizeof(void*);

std::size_t cost(const std::string& text) { return text.capacity() + kStateOverhead; }

}  // namespace

// A state equal to `same` shares its text; otherwise it is dumped compactly and held once.
History::Text History::keep(const nlohmann::json& state, const Text& same) {
    std::string text = state.dump();
    if (same && *same == text) return same;
    text.shrink_to_fit();  // the dump grows geometrically: hold (and count) only what the text needs
    bytes_ += cost(text);
    return std::make_shared<const std::string>(std::move(text));
}

// A state's bytes are returned when the last step holding it lets go.
void History::release(Stored& step) {
    for (Text* text : {&step.before, &step.after}) {
        if (*text && text->use_count() == 1) bytes_ -= cost(**text);
        text->reset();
    }
    bytes_ -= step.label.capacity() + sizeof(Stored);
}

std::size_t History::push(const HistoryStep& step) {
    while (steps_.size() > position_) {
        release(steps_.back());
        steps_.pop_back();
    }
    if (saved_ > position_) saved_ = kNotReachable;  // the saved state can no longer be reached
    const Text previous = steps_.empty() ? nullptr : steps_.back().after;
    Stored stored{step.label, keep(step.before, previous), nullptr, step.selectionBefore, step.selectionAfter};
    stored.after = keep(step.after, stored.before);
    bytes_ += stored.label.capacity() + sizeof(Stored);
    steps_.push_back(std::move(stored));
    position_ = steps_.size();
    return dropOldest();
}

// The newest step always stays, so the edit just made can be undone whatever its size.
std::size_t History::dropOldest() {
    std::size_t dropped = 0;
    while (bytes_ > limit_ && steps_.size() > 1) {
        release(steps_.front());
        steps_.pop_front();
        --position_;
        saved_ = saved_ == 0 || saved_ == kNotReachable ? kNotReachable : saved_ - 1;
        ++dropped;
    }
    dropped_ += dropped;
    return dropped;
}

std::optional<HistoryState> History::peekUndo() const {
    if (!canUndo()) return std::nullopt;
    const Stored& step = steps_[position_ - 1];
    return HistoryState{nlohmann::json::parse(*step.before), step.selectionBefore};
}

std::optional<HistoryState> History::peekRedo() const {
    if (!canRedo()) return std::nullopt;
    const Stored& step = steps_[position_];
    return HistoryState{nlohmann::json::parse(*step.after), step.selectionAfter};
}

void History::undo() {
    if (canUndo()) --position_;
}

void History::redo() {
    if (canRedo()) ++position_;
}

void History::clear() {
    steps_.clear();
    position_ = 0;
    saved_ = 0;
    bytes_ = 0;
    dropped_ = 0;
}

}  // namespace nimbus::sandbox::editor
