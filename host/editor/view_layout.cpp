#include "editor/view_layout.hpp"

#include <algorithm>

namespace animator {

ScreenRect view_rect(double window_width, double window_height, const std::vector<PanelPlace> &panels) {
    double left = 0.0, right = window_width;
    for (const PanelPlace &p : panels) {
        if (p.collapsed || p.rect.width <= 0.0) continue;
        const double centre = p.rect.x + p.rect.width / 2.0;
        if (centre < window_width / 2.0) left = std::max(left, p.rect.x + p.rect.width);
        else right = std::min(right, p.rect.x);
    }
    left = std::clamp(left, 0.0, window_width);
    right = std::clamp(right, 0.0, window_width);
    if (right - left < kMinViewWidth) right = window_width; // under the right panel
    if (right - left < kMinViewWidth) left = 0.0;           // the whole window
    return {left, 0.0, right - left, window_height};
}

} // namespace animator
