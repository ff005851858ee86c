#include "editor/view_layout.hpp"

#include <algorithm>

namespace animator {

ScreenRect view_rect(double window_width, double window_height, const std::vector<PanelPlace> &panels) {
    double left = 0.0, right = window_width, bottom = window_height;
    for (const PanelPlace &p : panels) {
        if (p.collapsed || p.rect.width <= 0.0) continue;
        if (p.bottom) {
            bottom = std::min(bottom, p.rect.y);
            continue;
        }
        const double centre = p.rect.x + p.rect.width / 2.0;
        if (centre < window_width / 2.0) left = std::max(left, p.rect.x + p.rect.width);
        else right = std::min(right, p.rect.x);
    }
    left = std::clamp(left, 0.0, window_width);
    right = std::clamp(right, 0.0, window_width);
    if (right - left < kMinViewWidth) right = window_width; // under the right panel
    if (right - left < kMinViewWidth) left = 0.0;           // the whole window
    bottom = std::clamp(bottom, 0.0, window_height);
    return {left, 0.0, right - left, bottom};
}

double bottom_panel_height(double window_height) {
    return std::max(0.0, std::min(kBottomPanelHeight, kBottomPanelShare * window_height));
}

ScreenRect bottom_panel_rect(double window_width, double window_height, double height,
                             const std::vector<PanelPlace> &side_panels) {
    const double top = window_height - height;
    double left = 0.0, right = window_width;
    for (const PanelPlace &p : side_panels) {
        if (p.collapsed || p.bottom || p.rect.width <= 0.0 || p.rect.y + p.rect.height <= top) continue;
        const double centre = p.rect.x + p.rect.width / 2.0;
        if (centre < window_width / 2.0) left = std::max(left, p.rect.x + p.rect.width);
        else right = std::min(right, p.rect.x);
    }
    left = std::clamp(left, 0.0, window_width);
    right = std::clamp(right, left, window_width);
    if (right - left < kMinViewWidth) { // the panels leave too little: across the window
        left = 0.0;
        right = window_width;
    }
    return {left, top, right - left, height};
}

} // namespace animator
