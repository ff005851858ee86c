// The undo history of a document: one stack per keyframe for the edits of that keyframe (seed,
// "Keys": "each keyframe has its own undo stack"), plus one stack for edits of the whole
// document. Undo at a keyframe takes back the latest edit of either that keyframe's stack or the
// document's stack; redo brings back the latest one undone there.
#pragma once

#include "document/edits.hpp"

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <vector>

namespace animator {

class EditHistory {
  public:
    // Applies the edit and records it. If apply() throws, nothing is recorded and the error
    // propagates. A new edit clears what could be redone on its stack.
    void perform(Document &doc, std::unique_ptr<Edit> edit);

    // With `current_keyframe_ms` the keyframe the user is at. Return false when there is
    // nothing to undo or redo there.
    bool undo(Document &doc, std::int64_t current_keyframe_ms);
    bool redo(Document &doc, std::int64_t current_keyframe_ms);
    bool can_undo(std::int64_t current_keyframe_ms) const;
    bool can_redo(std::int64_t current_keyframe_ms) const;

    // How many edits can be undone on one stack (nullopt: the document's stack).
    std::size_t undo_depth(std::optional<std::int64_t> keyframe_ms) const;

    void clear();

  private:
    struct Entry {
        std::unique_ptr<Edit> edit;
        std::uint64_t order; // when it was last performed, redone or undone
    };
    struct Stack {
        std::vector<Entry> done;
        std::vector<Entry> undone;
    };

    Stack &stack_for(std::optional<std::int64_t> keyframe_ms);
    const Stack *find_stack(std::optional<std::int64_t> keyframe_ms) const;
    // The stack (of the keyframe's and the document's) whose `list` top is latest, or null.
    Stack *latest(std::int64_t keyframe_ms, std::vector<Entry> Stack::*list);
    // Undo (from done to undone: revert) or redo (from undone to done: apply) the latest entry.
    bool move_latest(Document &doc, std::int64_t keyframe_ms, std::vector<Entry> Stack::*from,
                     std::vector<Entry> Stack::*to);

    std::map<std::int64_t, Stack> keyframe_stacks_;
    Stack document_stack_;
    std::uint64_t clock_ = 0;
};

} // namespace animator
