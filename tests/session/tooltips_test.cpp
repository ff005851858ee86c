// Every control of the editor's panels says what it does when the mouse rests on it (issue 17's
// "a tooltip on every control"). Dear ImGui runs here without a window or a GPU (its frames
// need no backend), the panels are drawn as the editor draws them at 1280x720, and the mouse is
// swept over the whole screen: wherever ImGui finds a control under it (its hovered item), a
// tooltip window must have been drawn in that same frame. Nothing lists the controls, so a
// control added later without a tooltip fails here too. The frame of a window (title bar,
// scrollbars, resize grips) is ImGui's own, not ours, and is left out.
#include "editor/editor_panels.hpp"
#include "editor/editor_session.hpp"

#include "support.hpp"

#include <catch2/catch.hpp>
#include <imgui.h>
#include <imgui_internal.h>

#include <map>
#include <sstream>

using namespace animator;
using namespace animator::test;

namespace {

constexpr float kWidth = 1280.0f, kHeight = 720.0f;

class HeadlessImGui {
  public:
    HeadlessImGui() {
        ImGui::CreateContext();
        ImGuiIO &io = ImGui::GetIO();
        io.IniFilename = nullptr;
        io.DisplaySize = ImVec2(kWidth, kHeight);
        io.DeltaTime = 1.0f / 60.0f;
        unsigned char *pixels = nullptr;
        int w = 0, h = 0;
        io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h); // the font atlas, as a backend would upload it
        ImGui::StyleColorsDark();
    }
    ~HeadlessImGui() { ImGui::DestroyContext(); }
    HeadlessImGui(const HeadlessImGui &) = delete;
    HeadlessImGui &operator=(const HeadlessImGui &) = delete;
};

struct Frame {
    ImGuiID hovered = 0;
    bool tooltip = false;
    bool in_content = false; // the mouse is in the hovered window's content, not its frame
    std::string window;
};

// One frame with the mouse at (x, y): what was under it and whether a tooltip was drawn.
Frame frame_at(Panels &panels, EditorSession &session, float x, float y, double &wall) {
    ImGuiIO &io = ImGui::GetIO();
    io.MousePos = ImVec2(x, y);
    ImGui::NewFrame();
    panels.draw(session, kWidth, kHeight, wall += 1.0 / 60.0);
    ImGuiContext &g = *GImGui;
    Frame f;
    f.hovered = g.HoveredId;
    if (ImGuiWindow *tip = ImGui::FindWindowByName("##Tooltip_00")) f.tooltip = tip->Active;
    if (ImGuiWindow *w = g.HoveredWindow) {
        f.window = w->Name;
        const ImRect &inner = w->InnerClipRect;
        // The resize grip in the bottom right corner of a resizable window is its frame too.
        const ImGuiWindow *root = w->RootWindow;
        const bool grip = !(root->Flags & ImGuiWindowFlags_NoResize) &&
                          x > root->Pos.x + root->Size.x - 24.0f && y > root->Pos.y + root->Size.y - 24.0f;
        f.in_content = inner.Contains(ImVec2(x, y)) && !grip;
    }
    ImGui::EndFrame();
    return f;
}

// Sweeps the screen every `step` pixels and returns where a control had no tooltip, as
// "window (x, y)" lines, one per control (its first place found).
std::string controls_without_tooltip(Panels &panels, EditorSession &session, int *controls_seen) {
    double wall = 0.0;
    for (int i = 0; i < 5; ++i) frame_at(panels, session, -100.0f, -100.0f, wall); // windows placed
    std::map<ImGuiID, std::string> missing;
    std::map<ImGuiID, bool> seen;
    constexpr float step = 5.0f;
    for (float y = 1.0f; y < kHeight; y += step)
        for (float x = 1.0f; x < kWidth; x += step) {
            const Frame f = frame_at(panels, session, x, y, wall);
            if (f.hovered == 0 || !f.in_content) continue;
            seen[f.hovered] = true;
            if (!f.tooltip && !missing.count(f.hovered)) {
                std::ostringstream where;
                where << f.window << " (" << x << ", " << y << ")";
                missing[f.hovered] = where.str();
            }
        }
    *controls_seen = static_cast<int>(seen.size());
    std::string out;
    for (const auto &[id, where] : missing) out += where + "\n";
    return out;
}

} // namespace

TEST_CASE("every control of the Animator Interface, the Outliner and the Timeline has a tooltip", "[session][tooltips]") {
    Environment env;
    EditorSession session(env);
    std::string error;
    REQUIRE(session.open(source_dir() / "assets" / "scenes" / "simple.lua", error));
    HeadlessImGui imgui;
    Panels panels(env);
    int seen = 0;
    const std::string missing = controls_without_tooltip(panels, session, &seen);
    INFO("controls without a tooltip (window, first place the mouse found them):\n" << missing);
    CHECK(missing.empty());
    // The sweep found the controls: the mode buttons, sliders, buttons, the Outliner's rows...
    CHECK(seen >= 25);
}

TEST_CASE("every control of the Model Interface has a tooltip, with one model and with several selected", "[session][tooltips]") {
    Environment env;
    EditorSession session(env);
    std::string error;
    REQUIRE(session.open(source_dir() / "assets" / "scenes" / "simple.lua", error));
    const int ball = session.document().find_model("ball"), cube = session.document().find_model("cube");
    REQUIRE(ball >= 0);
    REQUIRE(cube >= 0);
    HeadlessImGui imgui;
    Panels panels(env);
    int seen = 0;
    session.click(ball, false);
    std::string missing = controls_without_tooltip(panels, session, &seen);
    INFO("one model selected; controls without a tooltip:\n" << missing);
    CHECK(missing.empty());
    const int seen_one = seen;
    session.click(cube, true); // mixed fields
    missing = controls_without_tooltip(panels, session, &seen);
    INFO("two models selected; controls without a tooltip:\n" << missing);
    CHECK(missing.empty());
    CHECK(seen_one >= 40); // the Animator Interface's and the Model Interface's
}
