// The Transform section at the end of the Model Interface (transform_fields.hpp): three rows
// of numbers, dragged or CTRL+clicked and typed, each change let go or entered one undoable
// edit keying the selected models at the current time.
#pragma once

#include "editor/editor_session.hpp"
#include "editor/transform_fields.hpp"

#include <optional>
#include <string>

namespace animator {

class TransformPanel {
  public:
    // Inside the Model Interface's window. True when a change was committed; `error` says why
    // it was refused (the document unchanged); `note`, which turns a joint's range stopped.
    bool draw(EditorSession &session, std::string &error, std::string &note);

  private:
    std::optional<TransformValues> shown_, draft_; // while a row is held or typed into
};

} // namespace animator
