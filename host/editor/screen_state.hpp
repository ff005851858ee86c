// What the editor's panels show that can change with no input event: playback reaching the
// end, a bake slice, an undo's effect on Undo/Redo, a new status message, the title. The window
// compares it before and after the work it does between frames (editor_app.cpp) and draws one
// more frame when it changed, so the screen is never stale, yet sleeps when nothing changes.
#pragma once

#include "editor/editor_session.hpp"

#include <cstdint>
#include <string>

namespace animator {

struct ScreenState {
    bool playing = false;
    std::int64_t time_ms = 0;
    std::string bake; // bake_status(): changes with each tenth of a second baked
    bool can_undo = false, can_redo = false;
    std::uint64_t version = 0;
    std::string title;
    std::string message; // the status message

    bool operator==(const ScreenState &o) const {
        return playing == o.playing && time_ms == o.time_ms && bake == o.bake && can_undo == o.can_undo &&
               can_redo == o.can_redo && version == o.version && title == o.title && message == o.message;
    }
    bool operator!=(const ScreenState &o) const { return !(*this == o); }
};

ScreenState screen_state(const EditorSession &session, const std::string &message);

} // namespace animator
