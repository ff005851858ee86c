#include "editor/screen_state.hpp"

#include "editor/status_line.hpp"

namespace animator {

ScreenState screen_state(const EditorSession &session, const std::string &message) {
    ScreenState s;
    s.playing = session.playing();
    s.time_ms = session.time_ms();
    s.bake = bake_status(session);
    s.can_undo = session.can_undo();
    s.can_redo = session.can_redo();
    s.version = session.version();
    s.title = session.title();
    s.message = message;
    return s;
}

} // namespace animator
