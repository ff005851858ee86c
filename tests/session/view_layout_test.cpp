// Where the 3D view goes (editor/view_layout.hpp): between the panels, never under them, and
// still wide enough in a small window.
#include "editor/view_layout.hpp"

#include <catch2/catch.hpp>

using namespace animator;

namespace {
PanelPlace panel(double x, double width, bool collapsed = false) { return {{x, 10, width, 500}, collapsed}; }
} // namespace

TEST_CASE("the view takes the space between the left and the right panel", "[view_layout]") {
    const ScreenRect v = view_rect(1280, 720, {panel(10, 340), panel(910, 360)});
    CHECK(v.x == 350);
    CHECK(v.width == 560);
    CHECK(v.y == 0);
    CHECK(v.height == 720);
    // Without the Model Interface, up to the window's right edge.
    CHECK(view_rect(1280, 720, {panel(10, 340)}).width == 930);
    CHECK(view_rect(1280, 720, {}).width == 1280);
}

TEST_CASE("a collapsed panel leaves its space to the view", "[view_layout]") {
    const ScreenRect v = view_rect(1280, 720, {panel(10, 340, true), panel(910, 360)});
    CHECK(v.x == 0);
    CHECK(v.width == 910);
}

TEST_CASE("down to an 800 x 500 window the view is between the panels, narrower, it gives way", "[view_layout]") {
    // The editor's panels at 800 px: 340 at the left, 240 at the right; between them 200 px.
    const ScreenRect v = view_rect(800, 500, {panel(10, 340), panel(550, 240)});
    CHECK(v.x == 350);
    CHECK(v.width == 200);
    // At 760 px only 160 would be left: the right panel's space is given up first.
    const ScreenRect narrow = view_rect(760, 500, {panel(10, 340), panel(510, 240)});
    CHECK(narrow.x == 350);
    CHECK(narrow.width == 410);
    // A window narrower than a panel: the whole window.
    CHECK(view_rect(300, 200, {panel(10, 340)}).width == 300);
}

TEST_CASE("points inside the view are in it, the panels' are not", "[view_layout]") {
    const ScreenRect v = view_rect(1280, 720, {panel(10, 340), panel(910, 360)});
    CHECK(v.contains(630, 360));
    CHECK_FALSE(v.contains(100, 360));
    CHECK_FALSE(v.contains(1000, 360));
    CHECK_FALSE(v.contains(630, 720));
}

namespace {
PanelPlace bottom_panel(double x, double y, double width, double height, bool collapsed = false) {
    return {{x, y, width, height}, collapsed, true};
}
} // namespace

TEST_CASE("the Timeline along the bottom: the view ends at its top, and takes the height back collapsed", "[view_layout]") {
    // At 1280 x 720: the Timeline 160 px tall right of the Animator Interface.
    const ScreenRect v = view_rect(1280, 720, {panel(10, 340), bottom_panel(350, 560, 930, 160), panel(910, 240)});
    CHECK(v.x == 350);
    CHECK(v.width == 560);
    CHECK(v.y == 0);
    CHECK(v.height == 560);
    CHECK_FALSE(v.contains(630, 600));
    // Collapsed to its title bar at the bottom edge: the whole height again (the bar covers it).
    const ScreenRect c = view_rect(1280, 720, {panel(10, 340), bottom_panel(350, 701, 930, 19, true)});
    CHECK(c.height == 720);
    CHECK(c.width == 930);
    // A bottom panel is not a side panel, though its centre is in the right half.
    CHECK(view_rect(1280, 720, {bottom_panel(0, 560, 1280, 160)}).width == 1280);
}

TEST_CASE("the Timeline is 160 px tall, less in a small window, and spans what the side panels leave", "[view_layout]") {
    CHECK(bottom_panel_height(720) == 160);
    CHECK(bottom_panel_height(300) == 120);
    // The Animator Interface reaches down into the Timeline's band: the Timeline starts right of it.
    // The Model Interface ends above the band (the editor keeps it there): it is not in the way.
    const std::vector<PanelPlace> sides = {{{10, 10, 340, 700}, false}, {{910, 10, 360, 540}, false}};
    const ScreenRect t = bottom_panel_rect(1280, 720, 160, sides);
    CHECK(t.x == 350);
    CHECK(t.y == 560);
    CHECK(t.width == 930);
    CHECK(t.height == 160);
    // Collapsed, or short enough, the Animator Interface leaves the whole width.
    CHECK(bottom_panel_rect(1280, 720, 160, {{{10, 10, 340, 19}, true}}).x == 0);
    CHECK(bottom_panel_rect(1280, 720, 160, {{{10, 10, 340, 500}, false}}).width == 1280);
    // A right panel reaching down ends it at its left edge.
    const ScreenRect r = bottom_panel_rect(1280, 720, 160, {{{10, 10, 340, 700}, false}, {{910, 10, 360, 700}, false}});
    CHECK(r.x == 350);
    CHECK(r.width == 560);
    // Less than the view's least width left: across the whole window.
    CHECK(bottom_panel_rect(500, 400, 120, {{{10, 10, 340, 380}, false}}).width == 500);
}
