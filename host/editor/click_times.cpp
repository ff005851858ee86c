#include "editor/click_times.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <X11/Xlib.h>
#include <poll.h>

#include <cmath>

// glfw3native.h would declare these, but with GLFW_EXPOSE_NATIVE_X11 it also includes Xrandr's
// header, which nothing here needs (Debian's libglfw3 is built for X11: they are there).
extern "C" Display *glfwGetX11Display(void);
extern "C" Window glfwGetX11Window(GLFWwindow *window);

namespace animator {

int ClickCounter::press(int button, const PressStamp &at) {
    if (button < 0 || button >= kButtons) return 1;
    int &count = count_[button];
    PressStamp &last = last_[button];
    // Unsigned subtraction: the server's clock wraps every 49.7 days.
    const double gap = at.server_ms && last.server_ms
                           ? static_cast<std::uint32_t>(*at.server_ms - *last.server_ms) / 1000.0
                           : at.taken_s - last.taken_s;
    const bool again = count > 0 && gap >= 0.0 && gap < max_seconds_ &&
                       std::hypot(at.x - last.x, at.y - last.y) < max_distance_;
    count = again ? count + 1 : 1;
    last = at;
    return count;
}

ServerTimes::ServerTimes(GLFWwindow *window) {
    display_ = glfwGetX11Display();
    if (display_) window_ = glfwGetX11Window(window);
}

namespace {

struct Scan {
    Window window;
    std::deque<ServerTimes::Change> *out;
};

// XCheckIfEvent's predicate: notes each button change of the window and matches none, so the
// scan goes through the whole queue (reading what the connection holds) and takes nothing.
Bool note_button(Display *, XEvent *e, XPointer arg) {
    auto *scan = reinterpret_cast<Scan *>(arg);
    if ((e->type == ButtonPress || e->type == ButtonRelease) && e->xbutton.window == scan->window)
        scan->out->push_back({static_cast<int>(e->xbutton.button), e->type == ButtonPress,
                              static_cast<std::uint32_t>(e->xbutton.time)});
    return False;
}

// GLFW's button for an X button (x11_window.c): 1 left, 2 middle, 3 right, 4 to 7 the wheel
// (no button), 8 on the fourth button on.
int glfw_button(int x_button) {
    switch (x_button) {
    case Button1: return GLFW_MOUSE_BUTTON_LEFT;
    case Button2: return GLFW_MOUSE_BUTTON_MIDDLE;
    case Button3: return GLFW_MOUSE_BUTTON_RIGHT;
    default: return x_button >= 8 ? x_button - 5 : -1;
    }
}

} // namespace

void ServerTimes::read() {
    queued_.clear();
    XEvent event;
    Scan scan{static_cast<Window>(window_), &queued_};
    XCheckIfEvent(static_cast<Display *>(display_), &event, note_button, reinterpret_cast<XPointer>(&scan));
}

void ServerTimes::wait_on_connection(int timeout_ms) {
    auto *display = static_cast<Display *>(display_);
    if (XPending(display) > 0) return; // XPending sends what is buffered first, as GLFW does
    pollfd fd{ConnectionNumber(display), POLLIN, 0};
    ::poll(&fd, 1, timeout_ms);
}

void ServerTimes::poll() {
    if (display_) read();
    glfwPollEvents();
}

void ServerTimes::wait(double seconds) {
    const bool forever = seconds < 0.0;
    if (!display_) return forever ? glfwWaitEvents() : glfwWaitEventsTimeout(seconds);
    wait_on_connection(forever ? -1 : static_cast<int>(std::ceil(seconds * 1000.0)));
    poll();
}

std::optional<std::uint32_t> ServerTimes::take(int button, bool press) {
    // GLFW hands the queue's events over in order; the wheel's have no button callback.
    while (!queued_.empty()) {
        const Change c = queued_.front();
        queued_.pop_front();
        if (glfw_button(c.x_button) == button && c.press == press) return c.ms;
    }
    return std::nullopt;
}

} // namespace animator
