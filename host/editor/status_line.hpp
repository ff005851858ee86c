// The status line under the Animator Interface's buttons: how fast the editor draws, and how
// far the physics is baked, in words a user can read at a glance ("physics.custom: baked to
// 12.3 s of 20 s"). The texts are pure functions of the session, so they are tested without a
// window (tests/session/status_line_test.cpp).
#pragma once

#include "editor/editor_session.hpp"

#include <deque>
#include <string>

namespace animator {

// "physics.custom: baked, 20 s", "physics.custom: baked to 12.3 s of 20 s", or
// "physics.custom: bake failed at 3.2 s" (the reason is shown apart, it can be long).
std::string bake_status(const EditorSession &session);

// Frames per second over the last second the editor drew. An idle editor draws nothing, and
// then says so instead of showing the rate of its last burst of frames.
class FrameRate {
  public:
    // A frame was drawn at `wall` seconds.
    void frame(double wall);
    // The editor went to sleep: nothing is drawn until the next event.
    void idle() { times_.clear(); }
    // "60 fps", or "idle" when no frame was drawn since the editor last slept (or only one).
    std::string text() const;

  private:
    std::deque<double> times_;
};

} // namespace animator
