// Where the 3D view goes: the space the panels leave. The Animator Interface sits at the left,
// the Model Interface at the right; the view is drawn between them (and picks there), so no
// panel covers the scene. A collapsed panel (its title bar only) leaves the space to the view;
// a panel moved into the middle covers it, as the user chose. Pure, tested without a window
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
};

// Narrower than this, the view gives up the right panel's space first, then the left's (the
// panel then covers part of it). At 800 x 500 the panels (340 and 240 px) leave exactly this.
constexpr double kMinViewWidth = 200.0;

// The view: full height, from the right edge of the panels whose centre is in the left half of
// the window to the left edge of those in the right half.
ScreenRect view_rect(double window_width, double window_height, const std::vector<PanelPlace> &panels);

} // namespace animator
