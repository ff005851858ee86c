#include "document/history.hpp"

namespace animator {

EditHistory::Stack &EditHistory::stack_for(std::optional<std::int64_t> keyframe_ms) {
    return keyframe_ms ? keyframe_stacks_[*keyframe_ms] : document_stack_;
}

const EditHistory::Stack *EditHistory::find_stack(std::optional<std::int64_t> keyframe_ms) const {
    if (!keyframe_ms) return &document_stack_;
    auto it = keyframe_stacks_.find(*keyframe_ms);
    return it == keyframe_stacks_.end() ? nullptr : &it->second;
}

void EditHistory::perform(Document &doc, std::unique_ptr<Edit> edit) {
    edit->apply(doc);
    // A keyframe made anew starts with an empty history; an older keyframe that was at the
    // same time and was deleted takes its history with it.
    for (std::int64_t created : edit->creates_keyframes()) keyframe_stacks_.erase(created);
    Stack &stack = stack_for(edit->keyframe());
    stack.undone.clear();
    stack.done.push_back(Entry{std::move(edit), ++clock_});
}

EditHistory::Stack *EditHistory::latest(std::int64_t keyframe_ms,
                                        std::vector<Entry> Stack::*list) {
    Stack *best = (document_stack_.*list).empty() ? nullptr : &document_stack_;
    auto it = keyframe_stacks_.find(keyframe_ms);
    if (it != keyframe_stacks_.end() && !(it->second.*list).empty()) {
        Stack *own = &it->second;
        if (!best || (own->*list).back().order > (best->*list).back().order) best = own;
    }
    return best;
}

bool EditHistory::move_latest(Document &doc, std::int64_t keyframe_ms,
                              std::vector<Entry> Stack::*from, std::vector<Entry> Stack::*to) {
    Stack *stack = latest(keyframe_ms, from);
    if (!stack) return false;
    Entry entry = std::move((stack->*from).back());
    if (from == &Stack::done)
        entry.edit->revert(doc);
    else
        entry.edit->apply(doc);
    (stack->*from).pop_back();
    entry.order = ++clock_;
    (stack->*to).push_back(std::move(entry));
    return true;
}

bool EditHistory::undo(Document &doc, std::int64_t current_keyframe_ms) {
    return move_latest(doc, current_keyframe_ms, &Stack::done, &Stack::undone);
}

bool EditHistory::redo(Document &doc, std::int64_t current_keyframe_ms) {
    return move_latest(doc, current_keyframe_ms, &Stack::undone, &Stack::done);
}

bool EditHistory::can_undo(std::int64_t current_keyframe_ms) const {
    const Stack *own = find_stack(current_keyframe_ms);
    return !document_stack_.done.empty() || (own && !own->done.empty());
}

bool EditHistory::can_redo(std::int64_t current_keyframe_ms) const {
    const Stack *own = find_stack(current_keyframe_ms);
    return !document_stack_.undone.empty() || (own && !own->undone.empty());
}

std::size_t EditHistory::undo_depth(std::optional<std::int64_t> keyframe_ms) const {
    const Stack *stack = find_stack(keyframe_ms);
    return stack ? stack->done.size() : 0;
}

void EditHistory::clear() {
    keyframe_stacks_.clear();
    document_stack_ = Stack{};
    clock_ = 0;
}

} // namespace animator
