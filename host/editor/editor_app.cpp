#include "editor/editor_app.hpp"

#include "audio/live_player.hpp"
#include "editor/click_times.hpp"
#include "editor/editor_panels.hpp"
#include "editor/editor_session.hpp"
#include "editor/frame_budget.hpp"
#include "editor/gizmo_drawing.hpp"
#include "editor/help.hpp"
#include "editor/recovery.hpp"
#include "editor/screen_state.hpp"
#include "editor/status_line.hpp"
#include "editor/view_layout.hpp"
#include "render/renderer.hpp"

#include <glad/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>

#include <dlfcn.h>
#include <link.h>
#include <malloc.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <iostream>
#include <memory>
#include <thread>
#include <vector>

namespace animator {

namespace {

// What GLFW reported since the last frame, in order: the 1.86 ImGui backend keeps only the
// state of keys and buttons, so a press and release between two frames (xdotool's `key x`)
// would be lost without a queue of our own.
struct InputEvent {
    enum Kind { Key, Press, Release, Scroll } kind;
    int code = 0; // the key, or the mouse button
    int mods = 0;
    double x = 0, y = 0; // the cursor (screen coordinates) for buttons; the offset for scroll
};

// A double-click: two presses within half a second (as on Windows) and 6 pixels (ImGui's).
constexpr double kDoubleClickSeconds = 0.5;
constexpr double kDoubleClickPixels = 6.0;

struct WindowState {
    std::deque<InputEvent> events;
    bool woke = false; // anything at all happened: draw a few frames
    // Keys, buttons and scroll notches handled, and cursor moves: the readiness signal
    // (announce_idle) says how many, so a test knows its input was seen before the editor slept.
    std::uint64_t inputs = 0, moves = 0;
    bool close_requested = false;
    double cursor_x = 0, cursor_y = 0; // from the last motion event, in event order
    bool cursor_known = false;
    // ImGui 1.86 reads keys as up or down once a frame, so a key pressed and released between
    // two frames (a fast typist, xdotool) would never reach a text field: keys reach ImGui from
    // this queue, at most one change of each key per frame.
    GLFWkeyfun imgui_key = nullptr;
    struct KeyChange {
        int key, scancode, action, mods;
    };
    std::deque<KeyChange> imgui_keys;
    // The same for mouse buttons: the 1.86 backend sees one press of a button a frame, so a
    // double-click whose two clicks both came during one slow frame (a busy machine) was one
    // click to ImGui. Its button changes wait here and reach it one a frame (replaying: our own
    // callback, which ImGui's calls first, has already had them).
    GLFWmousebuttonfun imgui_mouse = nullptr;
    struct ButtonChange {
        int button, action, mods;
        int clicks; // a press: how many in a row it made (2: a double-click), counted when it happened
    };
    std::deque<ButtonChange> imgui_buttons;
    bool replaying_buttons = false;
    // Clicks are counted by when the X server says they happened (click_times.hpp), not by the
    // frames that hand them to ImGui; the count of a press handed over this frame, by button,
    // replaces ImGui's after its NewFrame (count_imgui_clicks).
    ServerTimes *server_times = nullptr;
    ClickCounter clicks{kDoubleClickSeconds, kDoubleClickPixels};
    int clicks_fed[ImGuiMouseButton_COUNT] = {};
};

WindowState &state_of(GLFWwindow *w) { return *static_cast<WindowState *>(glfwGetWindowUserPointer(w)); }

// A mouse button changed: an event for the editor's queue, where the pointer was. Called at
// once by the callback over ImGui's (install_queued_callbacks); ImGui's own calls it again when it
// is handed the change later, which is skipped.
void on_mouse_button(GLFWwindow *w, int button, int action, int mods) {
    auto &s = state_of(w);
    if (s.replaying_buttons) return;
    s.woke = true;
    ++s.inputs;
    // Where the pointer was when the button changed: the last motion event's place. (On X11
    // glfwGetCursorPos asks the server where the pointer is now, which may be past moves
    // still queued: a drag released and moved on at once was dropped where it moved to.)
    double x = s.cursor_x, y = s.cursor_y;
    if (!s.cursor_known) glfwGetCursorPos(w, &x, &y);
    s.events.push_back({action == GLFW_PRESS ? InputEvent::Press : InputEvent::Release, button, mods, x, y});
}

void install_callbacks(GLFWwindow *window) {
    // Keys: installed over ImGui's own callback (see install_queued_callbacks), not under it.
    glfwSetMouseButtonCallback(window, on_mouse_button); // under ImGui's (install_queued_callbacks)
    glfwSetScrollCallback(window, [](GLFWwindow *w, double, double dy) {
        auto &s = state_of(w);
        s.woke = true;
        ++s.inputs;
        s.events.push_back({InputEvent::Scroll, 0, 0, 0, dy});
    });
    glfwSetCursorPosCallback(window, [](GLFWwindow *w, double x, double y) {
        auto &s = state_of(w);
        s.woke = true;
        ++s.moves;
        s.cursor_x = x;
        s.cursor_y = y;
        s.cursor_known = true;
    });
    glfwSetCharCallback(window, [](GLFWwindow *w, unsigned) { state_of(w).woke = true; });
    glfwSetWindowSizeCallback(window, [](GLFWwindow *w, int, int) { state_of(w).woke = true; });
    glfwSetWindowRefreshCallback(window, [](GLFWwindow *w) { state_of(w).woke = true; });
    glfwSetWindowFocusCallback(window, [](GLFWwindow *w, int) { state_of(w).woke = true; });
    glfwSetCursorEnterCallback(window, [](GLFWwindow *w, int) { state_of(w).woke = true; });
    glfwSetWindowCloseCallback(window, [](GLFWwindow *w) {
        auto &s = state_of(w);
        s.woke = true;
        s.close_requested = true;
        glfwSetWindowShouldClose(w, GLFW_FALSE); // the editor decides, after asking
    });
}

// The mouse in the 3D view: a press starts a drag (Camera mode: any button; other modes: the
// middle and right buttons), a left press and release without moving is a click that selects.
// In those modes a left press on a handle of the transform gizmo drags the handle instead.
// With Alt held (Blender's "emulate 3 button mouse" and Maya's navigation), a drag looks
// around in the free view instead: left orbits, middle pans, right zooms; no mode uses Alt.
class Pointer {
  public:
    void press(EditorSession &session, const InputEvent &e, const ScreenRect &view) {
        const int viewport_height = static_cast<int>(std::lround(view.height));
        if (button_ >= 0) return;
        button_ = e.code;
        start_ = glm::dvec2(e.x, e.y);
        if (e.code > GLFW_MOUSE_BUTTON_MIDDLE) return;
        if ((e.mods & GLFW_MOD_ALT) != 0) {
            session.set_free_view(true);
            view_start_ = session.view();
            viewport_height_ = viewport_height;
            looking_ = true;
            return;
        }
        const auto b = static_cast<DragButton>(e.code);
        if (b == DragButton::Left && session.mode() != EditMode::Camera) {
            const GizmoView gizmo_view = session.gizmo_view(static_cast<int>(std::lround(view.width)), viewport_height);
            gizmo_ = session.begin_gizmo_drag(start_ - glm::dvec2(view.x, view.y), gizmo_view);
            if (gizmo_) return;
        }
        if (session.mode() == EditMode::Camera || b != DragButton::Left) session.begin_drag(b, viewport_height);
    }
    // Returns the click's position when the release is a click of the left button.
    std::optional<glm::dvec2> release(EditorSession &session, const InputEvent &e) {
        if (e.code != button_) return std::nullopt;
        last_button_ = button_;
        button_ = -1;
        const glm::dvec2 delta = glm::dvec2(e.x, e.y) - start_;
        if (looking_) {
            look(session, delta);
            looking_ = false;
            return std::nullopt;
        }
        const bool click = std::abs(delta.x) < 4 && std::abs(delta.y) < 4;
        const bool on_gizmo = gizmo_;
        gizmo_ = false;
        if (click) {
            session.cancel_drag();
            if (on_gizmo) return std::nullopt; // a click on a handle selects nothing
            return e.code == GLFW_MOUSE_BUTTON_LEFT ? std::optional<glm::dvec2>(glm::dvec2(e.x, e.y)) : std::nullopt;
        }
        session.update_drag(delta);
        session.end_drag();
        return std::nullopt;
    }
    void move(EditorSession &session, glm::dvec2 cursor) {
        if (button_ < 0) return;
        if (looking_) look(session, cursor - start_);
        else session.update_drag(cursor - start_);
    }
    bool down() const { return button_ >= 0; }
    // ESC: a look-around drag goes back to where it began, as a drag does.
    void cancel(EditorSession &session) {
        if (looking_) session.set_view(view_start_);
        looking_ = false;
    }

  private:
    // The view is a function of the drag so far, from where it began (no accumulated error).
    void look(EditorSession &session, glm::dvec2 delta) {
        switch (button_ >= 0 ? button_ : last_button_) {
        case GLFW_MOUSE_BUTTON_LEFT: session.set_view(orbit(view_start_, delta)); break;
        case GLFW_MOUSE_BUTTON_MIDDLE: session.set_view(pan(view_start_, delta, viewport_height_)); break;
        default: session.set_view(zoom_drag(view_start_, delta)); break;
        }
    }

    int button_ = -1, last_button_ = -1;
    glm::dvec2 start_{0.0};
    bool looking_ = false;
    bool gizmo_ = false; // the left button drags a gizmo handle
    FreeView view_start_;
    int viewport_height_ = 1;
};

// Keys and mouse buttons go to the editor's queue at once and to ImGui through its own queues
// (WindowState::imgui_keys, imgui_buttons). Installed after ImGui's backend, whose callbacks
// they wrap.
void install_queued_callbacks(GLFWwindow *window) {
    state_of(window).imgui_key = glfwSetKeyCallback(window, [](GLFWwindow *w, int key, int scancode, int action, int mods) {
        auto &s = state_of(w);
        s.woke = true;
        ++s.inputs;
        if (action == GLFW_PRESS || action == GLFW_REPEAT) s.events.push_back({InputEvent::Key, key, mods, 0, 0});
        s.imgui_keys.push_back({key, scancode, action, mods});
    });
    // Mouse buttons: ours at once (where the pointer was), ImGui's from a queue
    // (feed_imgui_buttons), whose replay reaches ours again through ImGui's and is skipped.
    state_of(window).imgui_mouse = glfwSetMouseButtonCallback(window, [](GLFWwindow *w, int button, int action, int mods) {
        on_mouse_button(w, button, action, mods);
        auto &s = state_of(w);
        const auto server_ms = s.server_times ? s.server_times->take(button, action == GLFW_PRESS) : std::nullopt;
        const InputEvent &e = s.events.back(); // on_mouse_button's, where the pointer was
        const int clicks = action == GLFW_PRESS ? s.clicks.press(button, {server_ms, glfwGetTime(), e.x, e.y}) : 0;
        s.imgui_buttons.push_back({button, action, mods, clicks});
    });
}

// Before a frame, after feed_imgui_keys: hands ImGui the queued button changes, at most one of
// each button (so a second click of a double-click comes a frame after the first's release).
// True when it handed one: the frame's clock is then kept short, so that a click queued during
// a slow frame is as brief to ImGui as it was to the user (a button that repeats while held
// steps once).
bool feed_imgui_buttons(GLFWwindow *window) {
    auto &s = state_of(window);
    std::fill(std::begin(s.clicks_fed), std::end(s.clicks_fed), 0);
    std::vector<int> changed;
    bool fed = false;
    while (!s.imgui_buttons.empty()) {
        const auto b = s.imgui_buttons.front();
        if (std::find(changed.begin(), changed.end(), b.button) != changed.end()) break;
        changed.push_back(b.button);
        s.imgui_buttons.pop_front();
        if (s.imgui_mouse) {
            s.replaying_buttons = true;
            s.imgui_mouse(window, b.button, b.action, b.mods);
            s.replaying_buttons = false;
        }
        if (b.clicks > 0 && b.button >= 0 && b.button < ImGuiMouseButton_COUNT) s.clicks_fed[b.button] = b.clicks;
        fed = true;
    }
    return fed;
}

// After ImGui::NewFrame: a press handed over this frame counts as the click it was when it
// happened (feed_imgui_buttons), whatever ImGui's clock made of the frames between.
void count_imgui_clicks(const WindowState &s, ImGuiIO &io) {
    for (int b = 0; b < ImGuiMouseButton_COUNT; ++b) {
        if (s.clicks_fed[b] == 0 || !io.MouseClicked[b]) continue;
        io.MouseClickedCount[b] = io.MouseClickedLastCount[b] = static_cast<ImU16>(s.clicks_fed[b]);
        io.MouseDoubleClicked[b] = s.clicks_fed[b] == 2;
    }
}

// Before a frame: hands ImGui the queued key changes, stopping at a second change of a key it
// already got this frame (the rest wait for the next frame).
void feed_imgui_keys(GLFWwindow *window) {
    auto &s = state_of(window);
    std::vector<int> changed;
    while (!s.imgui_keys.empty()) {
        const auto k = s.imgui_keys.front();
        if (std::find(changed.begin(), changed.end(), k.key) != changed.end()) break;
        changed.push_back(k.key);
        s.imgui_keys.pop_front();
        if (s.imgui_key) s.imgui_key(window, k.key, k.scancode, k.action, k.mods);
    }
}

// The motion paths to draw, sampled again only when what they show can have changed (the
// document, the bake, the drag's own bake, which models show one), not on every frame drawn.
class PathCache {
  public:
    const std::vector<PathLines> &get(const EditorSession &s) {
        Key key{s.version(), s.timeline().baked_until(), s.preview_baked_until(), s.preview_version(), s.dragging(),
                s.path_models()};
        if (key == key_ && valid_) return lines_;
        key_ = key;
        valid_ = true;
        lines_.clear();
        for (const MotionPath &p : s.motion_paths()) {
            PathLines l;
            for (const glm::dvec3 &x : p.frames) l.frames.emplace_back(x);
            for (const glm::dvec3 &x : p.keys) l.keys.emplace_back(x);
            for (const glm::dvec3 &x : p.hits) l.hits.emplace_back(x);
            lines_.push_back(std::move(l));
        }
        return lines_;
    }

  private:
    struct Key {
        std::uint64_t version = 0;
        double baked = -1, preview = -1;
        std::uint64_t preview_version = 0;
        bool dragging = false;
        std::vector<int> models;
        bool operator==(const Key &o) const {
            return version == o.version && baked == o.baked && preview == o.preview &&
                   preview_version == o.preview_version && dragging == o.dragging && models == o.models;
        }
    };
    Key key_;
    bool valid_ = false;
    std::vector<PathLines> lines_;
};

// With ANIMATOR_EDITOR_SIGNALS set (the end-to-end tests), the editor says each time it goes
// to sleep with everything drawn: "animator: idle (inputs 12, moves 40, time 1234 ms)". A test
// waits for a line counting its own keys and clicks instead of for a fixed time, which a loaded
// machine can exceed; the time is the animation's, the one the screen shows, so a test that
// pauses playback after some real time checks the picture against the time the editor reached
// (a loaded machine pauses later) instead of against the real time it waited. Off by default:
// a user's terminal would get a line per mouse move.
bool signals_wanted() {
    const char *v = std::getenv("ANIMATOR_EDITOR_SIGNALS");
    return v && *v && std::strcmp(v, "0") != 0;
}

// ANIMATOR_EDITOR_SLOW_FRAMES=MS: every frame takes at least MS milliseconds. A test's stand-in
// for a busy machine (a sanitizer build while other tests run), where a frame can take longer
// than a double-click: what the user did must still come through as they did it.
double slow_frame_seconds() {
    const char *v = std::getenv("ANIMATOR_EDITOR_SLOW_FRAMES");
    return v ? std::max(0.0, std::atof(v)) / 1000.0 : 0.0;
}

void announce_idle(const WindowState &s, std::int64_t time_ms) {
    std::cout << "animator: idle (inputs " << s.inputs << ", moves " << s.moves << ", time " << time_ms << " ms)"
              << std::endl;
}

void glfw_error(int code, const char *description) {
    std::cerr << "animator: GLFW error " << code << ": " << description << "\n";
}

// Mesa's driver and its GL dispatch library stay loaded until the process ends, as
// render/offscreen_context.cpp does for EGL: glfwTerminate unloads them otherwise, and
// LeakSanitizer then reports what they still hold (libglapi's strdup'ed names, ~5 KB) as leaks
// of no module, which no suppression can name. Kept loaded, it stays reachable: no report.
int pin_gl_driver(dl_phdr_info *info, size_t, void *) {
    const char *name = info->dlpi_name;
    if (name && (std::strstr(name, "_dri.so") || std::strstr(name, "libglapi.so")))
        dlopen(name, RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE);
    return 0;
}

} // namespace

int run_editor(const EditorOptions &options) {
    // Per-frame allocations must not go back to the kernel each frame (docs/rendering.md).
    mallopt(M_MMAP_THRESHOLD, 32 << 20);
    mallopt(M_TRIM_THRESHOLD, 512 << 20);

    glfwSetErrorCallback(glfw_error);
    if (!glfwInit()) {
        std::cerr << "animator: cannot open a window: no display (set DISPLAY, or run under "
                     "xvfb-run; `animator render` draws without one)\n";
        return 1;
    }
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_STENCIL_BITS, 8);
    glfwWindowHint(GLFW_DEPTH_BITS, 24);
    GLFWwindow *window = glfwCreateWindow(options.width, options.height, "animator", nullptr, nullptr);
    if (!window) {
        std::cerr << "animator: cannot open an OpenGL 3.3 core window\n";
        glfwTerminate();
        return 1;
    }
    WindowState window_state;
    glfwSetWindowUserPointer(window, &window_state);
    ServerTimes server_times(window);
    window_state.server_times = &server_times;
    glfwMakeContextCurrent(window);
    glfwSwapInterval(1);
    if (gladLoadGL(reinterpret_cast<GLADloadfunc>(glfwGetProcAddress)) == 0) {
        std::cerr << "animator: glad could not load OpenGL 3.3\n";
        glfwDestroyWindow(window);
        glfwTerminate();
        return 1;
    }
    dl_iterate_phdr(pin_gl_driver, nullptr);
    install_callbacks(window); // before ImGui's, which call these after their own work

    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO &io = ImGui::GetIO();
    io.IniFilename = nullptr; // no imgui.ini left in the user's folder
    // Double-clicks are counted by the X server's times (count_imgui_clicks); ImGui's own
    // measure, between the frames that see the clicks, keeps to the same rule.
    io.MouseDoubleClickTime = static_cast<float>(kDoubleClickSeconds);
    io.MouseDoubleClickMaxDist = static_cast<float>(kDoubleClickPixels);
    ImGui::StyleColorsDark();
    ImGui_ImplGlfw_InitForOpenGL(window, true);
    install_queued_callbacks(window);
    ImGui_ImplOpenGL3_Init("#version 330 core");

    int exit_code = 0;
    {
        Environment env;
        Panels panels(env);
        panels.load_view_settings();
        EditorSession session(env);
        RenderOptions render_options;
        Renderer renderer(env.plugins, env.assets, render_options,
                          [&](const std::string &message) { panels.say(message, true); });
        // Sound while playing forward (docs/sound.md); without a device, one warning line.
        audio::LivePlayer player(env.assets, [&](const std::string &message) { panels.say(message, true); });
        double played_to = 0.0; // the animation time up to which sounds have been played

        const std::filesystem::path file = options.file.empty() ? EditorSession::demo_path(env.assets)
                                                                : std::filesystem::path(options.file);
        std::string error;
        if (file.empty()) {
            panels.say("no demo scene found; starting with an empty animation", true);
        } else if (!session.open(file, error)) {
            panels.show_error("Could not open " + file.string(), error);
        } else {
            panels.say(opened_message("opened " + file.string(), session.warnings()), !session.warnings().empty());
            if (!options.file.empty()) panels.files().remember(file); // Open Recent (not the demo)
        }
        // Autosave (recovery.hpp): work left unsaved by a crash or a kill is offered back.
        std::string autosave_warning;
        Autosaver autosaver(env.plugins, recovery_folder(), autosave_interval(&autosave_warning));
        if (!autosave_warning.empty()) panels.say(autosave_warning, true);
        if (const auto offer = autosaver.offer(file))
            panels.ask_to_recover(local_time_label(offer->written),
                                  "Recover opens it as unsaved changes to " +
                                      (file.empty() ? std::string("an untitled animation") : file.filename().string()) +
                                      "; Discard sets it aside.\nAutosaved in " + home_path(offer->file));

        // The 3D view drawn off the window, when anti-aliased or at a lower resolution; refused:
        // GL could not make one (said once), so the view is drawn on the window as it is.
        std::unique_ptr<OffscreenFramebuffer> view_buffer;
        bool view_buffer_refused = false;
        int asked_samples = 0, usable_samples = 1; // the View menu's, and what GL gives of it
        std::string said_fewer;                    // the last line saying GL gives fewer samples
        std::uint64_t drawn_version = ~std::uint64_t{0};
        std::string title;
        // The 3D view: the space the panels left in the last frame drawn, where clicks pick.
        ScreenRect view{0.0, 0.0, static_cast<double>(options.width), static_cast<double>(options.height)};
        Pointer pointer;
        int frames_to_draw = 3;
        // ImGui's fades run on its clock, not on a count of frames: a modal dialog dims the view
        // over about 0.17 s. After anything happened, frames go on (at most 60 a second) until
        // then, or the dimming stops part way when a few frames come fast.
        constexpr double kSettleSeconds = 0.3;
        double settle_until = glfwGetTime() + kSettleSeconds;
        bool quitting = false;
        const bool signals = signals_wanted();
        const double slow_frames = slow_frame_seconds();
        FrameRate frame_rate;
        PathCache path_lines;
        std::unique_ptr<ScreenOverlay> gizmo_overlay; // made with the first gizmo drawn
        // The View menu's settings as drawn: lowered while frames take longer than 1/60 s.
        FrameBudget frame_budget;
        // ANIMATOR_FRAME_BUDGET=off draws with the View settings as chosen however long frames
        // take (tools/editor_fps.sh measures each setting so).
        const char *budget_env = std::getenv("ANIMATOR_FRAME_BUDGET");
        const bool keep_budget = !(budget_env && std::string(budget_env) == "off");
        std::optional<ViewSettings> budgeted; // the View settings the budget started from
        double last_frame_at = -1.0;          // when the last frame drawn back to back ended
        long play_frames = 0;      // frames drawn since playback started
        double play_started = -1.0; // when it started (wall seconds), -1 while not playing
        std::uint64_t previewed = 0; // the drag's document last said baked (signals)
        while (!quitting) {
            const bool busy = session.playing() || session.baking() || pointer.down() || frames_to_draw > 0;
            if (busy || !window_state.imgui_keys.empty() || !window_state.imgui_buttons.empty()) server_times.poll();
            else if (panels.output_busy()) server_times.wait(1.0 / 30.0); // a render's progress
            else if (glfwGetTime() < settle_until) server_times.wait(1.0 / 60.0);
            else if (frame_rate.text() != "idle") {
                // One last frame, so the status line says "idle" rather than the rate of the
                // frames just drawn, which would stand still on the screen while it sleeps.
                frame_rate.idle();
                frames_to_draw = 1;
                server_times.poll();
            } else {
                if (signals) announce_idle(window_state, session.time_ms());
                // Asleep until the next event, or until an autosave is due (unsaved work only).
                if (const auto due = autosaver.seconds_to_wait(glfwGetTime())) server_times.wait(*due + 0.005);
                else server_times.wait();
            }
            if (window_state.woke) {
                frames_to_draw = 3; // ImGui settles within a few frames
                settle_until = glfwGetTime() + kSettleSeconds;
            }
            window_state.woke = false;

            ImGui_ImplOpenGL3_NewFrame();
            feed_imgui_keys(window);
            const bool buttons_fed = feed_imgui_buttons(window);
            ImGui_ImplGlfw_NewFrame();
            // A click that waited in the queue reaches ImGui as brief as it was (feed_imgui_buttons).
            if (buttons_fed || !window_state.imgui_buttons.empty()) io.DeltaTime = std::min(io.DeltaTime, 1.0f / 60.0f);
            ImGui::NewFrame();
            count_imgui_clicks(window_state, io);

            int fb_w = 0, fb_h = 0, win_w = 0, win_h = 0;
            glfwGetFramebufferSize(window, &fb_w, &fb_h);
            glfwGetWindowSize(window, &win_w, &win_h);
            const double to_fb = win_w > 0 ? static_cast<double>(fb_w) / win_w : 1.0;

            // Events, in the order they came. Keys typed into a text field are the field's.
            while (!window_state.events.empty()) {
                const InputEvent e = window_state.events.front();
                window_state.events.pop_front();
                switch (e.kind) {
                case InputEvent::Press:
                    // Drags are in window coordinates, so the viewport height is too (on a
                    // HiDPI screen the framebuffer has more pixels than the window): the 3D
                    // view's, which ends above the Timeline.
                    if (!io.WantCaptureMouse && !pointer.down()) pointer.press(session, e, view);
                    break;
                case InputEvent::Release:
                    if (auto click = pointer.release(session, e)) {
                        if (session.playing()) break;
                        // Picked in the view as drawn: its own pixels, from its top-left corner.
                        int model = -1;
                        renderer.set_hidden(session.hidden_models());
                        if (view.contains(click->x, click->y))
                            model = renderer.pick(session.shown_frame(), static_cast<int>(std::lround(view.width * to_fb)),
                                                  static_cast<int>(std::lround(view.height * to_fb)),
                                                  static_cast<int>((click->x - view.x) * to_fb),
                                                  static_cast<int>((click->y - view.y) * to_fb));
                        session.click(model, (e.mods & GLFW_MOD_CONTROL) != 0);
                    }
                    // A turn that a joint's range stopped says so (joint_clamp.hpp).
                    if (const std::string note = session.take_joint_note(); !note.empty()) panels.say(note);
                    break;
                case InputEvent::Scroll:
                    // In the free view the wheel zooms it; looking through the animated camera
                    // in Camera mode, it moves (and keys) that camera, as in the seed.
                    if (io.WantCaptureMouse) break;
                    if (session.free_view()) session.set_view(zoom_wheel(session.view(), e.y));
                    else session.scroll(e.y);
                    break;
                case InputEvent::Key: {
                    // Keys typed into a text field are the field's; with a dialog open (modal: it
                    // is answered first), `q` must not quit and SPACE not play behind it.
                    if (io.WantCaptureKeyboard || io.WantTextInput || panels.dialog_open()) break;
                    const bool ctrl = (e.mods & GLFW_MOD_CONTROL) != 0, shift = (e.mods & GLFW_MOD_SHIFT) != 0;
                    const bool alt = (e.mods & GLFW_MOD_ALT) != 0;
                    if (ctrl && (e.code == GLFW_KEY_N || e.code == GLFW_KEY_O || e.code == GLFW_KEY_S || e.code == GLFW_KEY_Q)) {
                        // The File menu's keys (file_menu.hpp).
                        if (e.code == GLFW_KEY_N) panels.files().new_file(session);
                        else if (e.code == GLFW_KEY_O) panels.files().open_file(session);
                        else if (e.code == GLFW_KEY_S && shift) panels.files().save_as(session);
                        else if (e.code == GLFW_KEY_S) panels.files().save(session);
                        else window_state.close_requested = true;
                    } else if (e.code == GLFW_KEY_SPACE) session.toggle_play(glfwGetTime());
                    else if ((e.code == GLFW_KEY_U && !ctrl) || (e.code == GLFW_KEY_Z && ctrl && !shift)) {
                        panels.undo(session);
                    } else if ((e.code == GLFW_KEY_R && !ctrl) || (e.code == GLFW_KEY_Z && ctrl && shift) ||
                               (e.code == GLFW_KEY_Y && ctrl)) {
                        panels.redo(session);
                    } else if (e.code == GLFW_KEY_X && !ctrl) {
                        const auto r = session.export_animation();
                        panels.say(r.message, !r.ok);
                    } else if (e.code == GLFW_KEY_Q && !ctrl) {
                        window_state.close_requested = true;
                    } else if (e.code == GLFW_KEY_I && !ctrl) {
                        // Blender's Insert Keyframe (ALT+I: Delete Keyframe), Maya's Set Key.
                        bool ok = false;
                        const std::string said = alt ? session.delete_keys_here(&ok) : session.insert_keys(&ok);
                        panels.say(said, !ok);
                    } else if (e.code == GLFW_KEY_A && !ctrl && !shift) {
                        if (alt) session.select_none();
                        else session.select_all();
                        const std::size_t n = session.selection().size();
                        panels.say(alt ? "selected none" : "selected " + std::to_string(n) + (n == 1 ? " model" : " models"));
                    } else if (e.code == GLFW_KEY_H && !ctrl && !shift) {
                        const int n = alt ? session.show_all() : session.hide_selected();
                        panels.say(alt ? (n > 0 ? "every model shown" : "no model was hidden")
                                       : (n > 0 ? "hid " + std::to_string(n) + " model" + (n == 1 ? "" : "s") + " (ALT+H shows them)"
                                                : "nothing selected to hide"));
                    } else if (!ctrl && !alt && !shift &&
                               (e.code == GLFW_KEY_G || e.code == GLFW_KEY_K ||
                                e.code == GLFW_KEY_N || e.code == GLFW_KEY_TAB)) {
                        // Keys other programs bind: where to look here instead (help.cpp).
                        const std::string key = e.code == GLFW_KEY_TAB ? "TAB" : std::string(1, static_cast<char>('a' + (e.code - GLFW_KEY_A)));
                        if (const auto hint = familiar_key_hint(key)) panels.say(*hint);
                    } else if (e.code == GLFW_KEY_F12 && ctrl) {
                        panels.open_render();
                    } else if (e.code == GLFW_KEY_E && ctrl && shift) {
                        panels.open_export();
                    } else if (e.code == GLFW_KEY_F1) {
                        panels.toggle_help();
                    } else if (e.code == GLFW_KEY_ESCAPE && panels.help_open()) {
                        panels.close_help();
                    } else if (e.code == GLFW_KEY_ESCAPE) {
                        session.cancel_drag();
                        pointer.cancel(session);
                        panels.cancel_timeline_drag();
                    } else if (e.code == GLFW_KEY_DELETE) {
                        // The Timeline's selected keys, if any; else the selected models, asked first.
                        if (!panels.delete_keys(session)) panels.ask_delete_models(session);
                    } else if (e.code == GLFW_KEY_D && shift && !ctrl) {
                        panels.duplicate_models(session);
                    } else if (e.code == GLFW_KEY_A && shift && !ctrl) {
                        panels.ask_add_model();
                    } else if (e.code == GLFW_KEY_C && ctrl) {
                        panels.copy_keys(session); // never `c`'s free view
                    } else if (e.code == GLFW_KEY_V && ctrl) {
                        panels.paste_keys(session);
                    } else if ((e.code == GLFW_KEY_W || e.code == GLFW_KEY_E || e.code == GLFW_KEY_S) && !ctrl) {
                        // Maya's W and E, Blender's S; not during a drag (it would change what it does).
                        if (!pointer.down())
                            session.set_mode(e.code == GLFW_KEY_W   ? EditMode::Translate
                                             : e.code == GLFW_KEY_E ? EditMode::Rotate
                                                                    : EditMode::Scale);
                    } else if (e.code == GLFW_KEY_P && !ctrl) {
                        session.set_paths_on(!session.paths_on());
                    } else if ((e.code == GLFW_KEY_C && !ctrl) || e.code == GLFW_KEY_KP_0) {
                        session.set_free_view(!session.free_view());
                    } else if (e.code == GLFW_KEY_HOME || (e.code == GLFW_KEY_F && !ctrl) || e.code == GLFW_KEY_KP_DECIMAL) {
                        const bool selected = e.code != GLFW_KEY_HOME;
                        const double aspect = view.height > 0 ? view.width / view.height : 1.0;
                        if (!session.frame_models(selected, aspect))
                            panels.say(selected ? "nothing selected to frame" : "no model to frame");
                    } else if (e.code == GLFW_KEY_F2) {
                        if (session.last_selected() >= 0) panels.start_rename(session.last_selected());
                    } else if ((e.code == GLFW_KEY_LEFT || e.code == GLFW_KEY_RIGHT) && shift) {
                        // Blender's jump to the start or the end.
                        session.pause();
                        session.set_time_ms(e.code == GLFW_KEY_LEFT ? 0 : session.document().settings().max_time_ms);
                    } else if (e.code == GLFW_KEY_LEFT || e.code == GLFW_KEY_RIGHT) {
                        session.step_frames(e.code == GLFW_KEY_RIGHT ? 1 : -1);
                    } else if (e.code == GLFW_KEY_UP || e.code == GLFW_KEY_DOWN) {
                        // Up to the previous keyframe, as the keyframe list reads top to bottom.
                        session.jump_keyframe(e.code == GLFW_KEY_DOWN ? 1 : -1);
                    }
                    break;
                }
                }
            }
            double cx = 0, cy = 0;
            glfwGetCursorPos(window, &cx, &cy);
            // CTRL snaps a gizmo drag (gizmo.hpp), pressed or let go at any time during it.
            session.set_snap(glfwGetKey(window, GLFW_KEY_LEFT_CONTROL) == GLFW_PRESS ||
                             glfwGetKey(window, GLFW_KEY_RIGHT_CONTROL) == GLFW_PRESS);
            pointer.move(session, glm::dvec2(cx, cy));

            if (panels.files().take_quit_request()) window_state.close_requested = true;
            if (window_state.close_requested) {
                window_state.close_requested = false;
                if (session.dirty()) panels.ask_to_quit();
                else quitting = true;
            }
            panels.set_frame_rate(frame_rate.text());
            panels.draw(session, static_cast<float>(win_w), static_cast<float>(win_h), glfwGetTime());
            if (panels.quit_confirmed()) quitting = true;
            view = view_rect(win_w, win_h, panels.places());
            // A gizmo handle under the resting pointer says what dragging it does, as every
            // control does (drawn with this frame's panels; the gizmo itself is drawn below).
            if (!pointer.down() && !io.WantCaptureMouse && view.contains(cx, cy)) {
                const GizmoView gv = session.gizmo_view(static_cast<int>(std::lround(view.width)),
                                                        static_cast<int>(std::lround(view.height)));
                if (const auto gizmo = session.gizmo(gv))
                    if (const char *tip = gizmo_handle_tip(session.mode(), gizmo_hit(*gizmo, gv, glm::dvec2(cx - view.x, cy - view.y))))
                        ImGui::SetTooltip("%s", tip);
            }
            // While a turn is held by a joint's range, a tooltip at the cursor says so.
            if (pointer.down() && session.dragging())
                if (const std::string note = session.joint_note(); !note.empty()) ImGui::SetTooltip("%s", note.c_str());
            // What this frame's panels show; the work below (playback, the bake) may change it.
            const ScreenState shown = screen_state(session, panels.message());
            // A document opened from the File menu: its autosave, if any, is offered as at a start.
            if (const auto opened = panels.files().take_opened())
                if (const auto offer = autosaver.offer(*opened))
                    panels.ask_to_recover(local_time_label(offer->written),
                                          "Recover opens it as unsaved changes to " + opened->filename().string() +
                                              "; Discard sets it aside.\nAutosaved in " + home_path(offer->file));
            if (const auto recover = panels.take_recover_answer()) {
                std::string said;
                const bool ok = *recover ? autosaver.recover(session, said) : autosaver.discard(said);
                panels.say(said, !ok);
            }
            // Not in the middle of a drag (its flush to disk could stall it): when it ends.
            bool autosave_failed = false;
            if (!pointer.down())
                if (const std::string said = autosaver.tick(session, glfwGetTime(), &autosave_failed); !said.empty())
                    panels.say(said, autosave_failed);

            const bool was_playing = session.playing(), was_baking = session.baking();
            session.tick(glfwGetTime());
            if (was_playing && !session.playing()) panels.say("played to the end, " + std::to_string(session.time_ms()) + " ms");
            // How fast playback drew (docs/performance.md measures the editor with it): from the
            // first frame drawn playing to the end or a pause.
            if (session.playing() && play_started < 0.0) {
                play_frames = 0;
                play_started = glfwGetTime();
            } else if (!session.playing() && play_started >= 0.0) {
                const double took = glfwGetTime() - play_started;
                if (signals)
                    std::cout << "animator: played " << play_frames << " frames in " << took << " s ("
                              << (took > 0.0 ? static_cast<double>(play_frames) / took : 0.0) << " fps)" << std::endl;
                play_started = -1.0;
            }
            if (session.playing() && session.time() > played_to) {
                player.advance(session.timeline(), played_to, session.time());
            } else if (!session.playing() && played_to != session.time()) {
                player.stop_all(); // paused, scrubbed or jumped: silence, and start again from here
            }
            played_to = session.time();
            // Bake between frames: a slice small enough to keep playback and the mouse smooth.
            session.bake_some(session.playing() || pointer.down() ? 0.008 : 0.03);
            // A drag's own bake, for the motion paths to follow it (never blocking the drag).
            if (pointer.down()) {
                session.preview_some(0.008);
                if (signals && session.preview_baked_until() >= session.max_time() &&
                    session.preview_version() != previewed) {
                    previewed = session.preview_version();
                    std::cout << "animator: drag previewed (delta " << session.drag_delta().x << " " << session.drag_delta().y
                              << ")" << std::endl;
                }
            }
            if (was_baking && !session.baking()) std::cout << "animator: " << bake_status(session) << std::endl;

            if (drawn_version != session.version()) {
                try {
                    renderer.set_document(session.document(), session.meshes());
                    player.set_document(session.document());
                } catch (const std::exception &e) {
                    panels.say(e.what(), true);
                }
                drawn_version = session.version();
            }
            if (session.title() != title) {
                title = session.title();
                glfwSetWindowTitle(window, title.c_str());
            }

            ImGui::Render();
            // Behind the panels the background; the scene in the view between them.
            glBindFramebuffer(GL_FRAMEBUFFER, 0);
            glViewport(0, 0, fb_w, fb_h);
            glClearColor(render_options.background.r, render_options.background.g, render_options.background.b, 1.0f);
            glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
            RenderTarget target;
            target.x = static_cast<int>(std::lround(view.x * to_fb));
            target.width = static_cast<int>(std::lround(view.width * to_fb));
            target.height = static_cast<int>(std::lround(view.height * to_fb));
            target.y = fb_h - static_cast<int>(std::lround(view.y * to_fb)) - target.height; // GL's rows go up
            renderer.set_hidden(session.hidden_models()); // the Outliner's eyes (not drawn, not picked)
            // Frames back to back (playing, dragging): drawn at the frame budget's quality, and
            // timed for it.
            const bool moving = keep_budget && (session.playing() || pointer.down());
            if (target.width > 0 && target.height > 0) {
                // Anti-aliased: the scene drawn into a multisampled framebuffer of the view's size,
                // resolved onto the window (which needs no multisampled visual of its own).
                const ViewSettings &chosen = panels.view_settings();
                const ViewQuality chosen_quality{chosen.shadows, RenderOptions{}.shadow_map_size, chosen.msaa,
                                                 chosen.reflections ? RenderOptions{}.reflection_size : 0,
                                                 chosen.resolution, RenderOptions{}.detail_pixels,
                                                 RenderOptions{}.mirror_levels};
                if (budgeted != chosen) {
                    view_buffer_refused = false; // (tried again with the new settings)
                    frame_budget.choose(chosen_quality);
                    budgeted = chosen;
                }
                // The budget's quality while frames come back to back (playing, dragging); at rest
                // the view is drawn as chosen (the one frame drawn then may take its time), as
                // Blender's viewport draws at full resolution once navigation stops.
                const ViewQuality &quality = moving ? frame_budget.quality() : chosen_quality;
                if (quality.msaa != asked_samples) { // the View menu or the budget changed it
                    asked_samples = quality.msaa;
                    std::string fewer;
                    usable_samples = supported_samples(asked_samples, &fewer);
                    if (!fewer.empty() && fewer != said_fewer) panels.say(fewer, true);
                    said_fewer = fewer; // (said once, not at every start and stop of playback)
                }
                const int samples = usable_samples;
                // At a lower resolution the scene is drawn into a smaller framebuffer, stretched
                // onto the view (View > Resolution, or the frame budget).
                const int drawn_width = std::max(1, target.width * quality.resolution / 100),
                          drawn_height = std::max(1, target.height * quality.resolution / 100);
                const bool offscreen = !view_buffer_refused &&
                                       (samples > 1 || drawn_width != target.width || drawn_height != target.height);
                if (offscreen &&
                    (!view_buffer || view_buffer->width() != drawn_width ||
                     view_buffer->height() != drawn_height || view_buffer->samples() != samples)) {
                    view_buffer.reset();
                    try {
                        view_buffer = std::make_unique<OffscreenFramebuffer>(drawn_width, drawn_height, samples);
                    } catch (const std::exception &e) {
                        panels.say(std::string(e.what()) + "; drawing without anti-aliasing, at full resolution", true);
                        view_buffer_refused = true; // said once, not every frame
                    }
                }
                if (!offscreen) view_buffer.reset();
                const RenderTarget scene_target = view_buffer ? view_buffer->target() : target;
                renderer.set_shadows(quality.shadows, quality.shadow_map_size);
                renderer.set_reflections(quality.reflection_size);
                renderer.set_detail(quality.detail_pixels, quality.mirror_levels);
                renderer.draw(session.shown_frame(), scene_target, session.selection(),
                              session.overlapping_models());
                renderer.draw_paths(path_lines.get(session), scene_target);
                if (view_buffer) view_buffer->copy_to(target);
                // The gizmo over everything, its handle under the cursor (or dragged) highlighted.
                const GizmoView gizmo_view = session.gizmo_view(static_cast<int>(std::lround(view.width)),
                                                                static_cast<int>(std::lround(view.height)));
                // The scene's lights as markers where they are (none: the camera's own light).
                if (const auto &lights = session.document().settings().lights; !lights.empty()) {
                    if (!gizmo_overlay) gizmo_overlay = std::make_unique<ScreenOverlay>();
                    glBindFramebuffer(GL_FRAMEBUFFER, 0);
                    glViewport(target.x, target.y, target.width, target.height);
                    gizmo_overlay->draw(light_markers(lights, gizmo_view), static_cast<float>(view.width),
                                        static_cast<float>(view.height));
                }
                if (const auto gizmo = session.gizmo(gizmo_view)) {
                    GizmoHandle lit = session.gizmo_handle();
                    if (!pointer.down() && !io.WantCaptureMouse)
                        lit = gizmo_hit(*gizmo, gizmo_view, glm::dvec2(cx - view.x, cy - view.y));
                    if (!gizmo_overlay) gizmo_overlay = std::make_unique<ScreenOverlay>();
                    glBindFramebuffer(GL_FRAMEBUFFER, 0);
                    glViewport(target.x, target.y, target.width, target.height);
                    gizmo_overlay->draw(gizmo_triangles(gizmo_shapes(*gizmo, gizmo_view), lit),
                                        static_cast<float>(view.width), static_cast<float>(view.height));
                }
            }
            glBindFramebuffer(GL_FRAMEBUFFER, 0);
            glViewport(0, 0, fb_w, fb_h);
            ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
            glfwSwapBuffers(window);
            if (slow_frames > 0.0) std::this_thread::sleep_for(std::chrono::duration<double>(slow_frames));
            frame_rate.frame(glfwGetTime());
            // Frames back to back (playing, dragging) count against the budget; one line when it
            // lowers the view's quality (frame_budget.hpp).
            if (moving) {
                const double now = glfwGetTime();
                if (last_frame_at >= 0.0)
                    if (const auto lowered = frame_budget.frame(now - last_frame_at))
                        panels.say(*lowered); // the status line, and one line on stdout
                last_frame_at = now;
            } else {
                frame_budget.pause();
                last_frame_at = -1.0;
            }
            if (session.playing()) ++play_frames;
            if (frames_to_draw > 0) --frames_to_draw;
            // Playback ended, a bake slice, an undo's effect on the buttons, a new message: the
            // panels drawn above are already out of date, so one more frame shows it.
            if (screen_state(session, panels.message()) != shown) frames_to_draw = std::max(frames_to_draw, 1);
        }
        bool keep_failed = false;
        if (const std::string said = autosaver.quit(session, &keep_failed); !said.empty()) panels.say(said, keep_failed);
        exit_code = 0;
    }
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    glfwDestroyWindow(window);
    glfwTerminate();
    return exit_code;
}

} // namespace animator
