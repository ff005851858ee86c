// Where the 3D view goes: the space the panels leave. The Animator Interface sits at the left,
// the Model Interface at the right, the Timeline (editor/dope_sheet.hpp) along the bottom; the
// view is drawn between them and above the Timeline (and picks there), so no panel covers the
// scene. A collapsed panel (its title bar only) leaves the space to the view; a panel moved
// into the middle covers it, as the user chose. Pure, tested without a window
// (tests/session/view_layout_test.cpp).
#pragma once

#include <vector>

namespace animator {

struct ScreenRect {
    double x = 0, y = 0, width = 0, height = 0; // window coordinates, y down
    bool contains(double px, double py) const { return px >= x && px < x + width && py >= y && py < y + height; }
};

struct PanelPlace {
    ScreenRect rect;
    bool collapsed = false;
    bool bottom = false; // docked along the bottom (the Timeline), not at a side
};

// Narrower than this, the view gives up the right panel's space first, then the left's (the
// panel then covers part of it). At 800 x 500 the panels (340 and 240 px) leave exactly this.
constexpr double kMinViewWidth = 200.0;

// The view: from the right edge of the side panels whose centre is in the left half of the
// window to the left edge of those in the right half, and from the top down to the top of the
// bottom panel (the whole height while it is collapsed).
ScreenRect view_rect(double window_width, double window_height, const std::vector<PanelPlace> &panels);

// The Timeline's height at the bottom of the window: kBottomPanelHeight, but at most
// kBottomPanelShare of a small window's height.
constexpr double kBottomPanelHeight = 160.0;
constexpr double kBottomPanelShare = 0.4;
double bottom_panel_height(double window_height);

// Where the bottom panel goes, `height` tall at the window's bottom edge: across the window, less
// the side panels (not collapsed) that reach down into its band, from the right edge of those at
// the left to the left edge of those at the right.
ScreenRect bottom_panel_rect(double window_width, double window_height, double height,
                             const std::vector<PanelPlace> &side_panels);

} // namespace animator
