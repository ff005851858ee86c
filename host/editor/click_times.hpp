#pragma once
// Double-clicks as the user made them, not as the frames saw them.
//
// Dear ImGui 1.86 counts a click as a double-click when the frames that see its two presses are
// close enough on its clock. On a busy machine a frame can take longer than a double-click:
// two quick clicks were then two clicks, and (the editor's queue keeping its clock short while
// it replays what waited) two slow ones a double-click. The X server stamps every button press
// with the time it happened; ServerTimes reads those stamps from Xlib's queue before GLFW takes
// the events, and ClickCounter counts clicks by them.

#include <cstdint>
#include <deque>
#include <optional>

struct GLFWwindow;

namespace animator {

// When and where a button was pressed: the X server's time (milliseconds, wrapping at 2^32)
// when known, else the editor's clock (seconds) when it took the event.
struct PressStamp {
    std::optional<std::uint32_t> server_ms;
    double taken_s = 0.0;
    double x = 0.0, y = 0.0;
};

// Counts successive presses of each button as ImGui does (1 a click, 2 a double-click, 3 a
// triple...): a press within `max_seconds` of the last and within `max_distance` pixels of it
// adds one, any other starts again at 1. Times are the server's when both presses have one.
class ClickCounter {
  public:
    ClickCounter(double max_seconds, double max_distance) : max_seconds_(max_seconds), max_distance_(max_distance) {}
    int press(int button, const PressStamp &at);

  private:
    static constexpr int kButtons = 8;
    double max_seconds_, max_distance_;
    PressStamp last_[kButtons];
    int count_[kButtons] = {};
};

// The X server's time of each mouse button change still in Xlib's queue, for the window's
// GLFW callbacks to take in order. Off X11 (no display) it knows no times, and its waits are
// GLFW's own.
class ServerTimes {
  public:
    explicit ServerTimes(GLFWwindow *window);
    // glfwPollEvents, and glfwWaitEventsTimeout (seconds; below 0, glfwWaitEvents), reading the
    // queue's stamps first: waiting is done on the X connection, so an event that wakes the
    // editor is still in the queue to be read.
    void poll();
    void wait(double seconds = -1.0);
    // In a GLFW mouse button callback: the server's time of this change (GLFW's button and
    // action), if it was read before GLFW took it.
    std::optional<std::uint32_t> take(int button, bool press);

    struct Change {
        int x_button;
        bool press;
        std::uint32_t ms;
    };

  private:
    void wait_on_connection(int timeout_ms);
    void read();
    void *display_ = nullptr; // Display*
    unsigned long window_ = 0; // Window
    std::deque<Change> queued_;
};

} // namespace animator
