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

TEST_CASE("down to an 800 x 500 window the view is between the panels; narrower, it gives way", "[view_layout]") {
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
