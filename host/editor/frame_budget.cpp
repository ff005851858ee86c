#include "editor/frame_budget.hpp"

#include <algorithm>
#include <cstdio>

namespace animator {

FrameBudget::FrameBudget(double budget, int window)
    : budget_(budget), window_(std::max(window, 1)) {}

void FrameBudget::choose(const ViewQuality &chosen) {
    quality_ = chosen;
    times_.clear();
}

std::optional<std::string> FrameBudget::frame(double seconds) {
    times_.push_back(seconds);
    if (static_cast<int>(times_.size()) < window_) return std::nullopt;
    std::vector<double> sorted = times_;
    times_.clear();
    std::nth_element(sorted.begin(),
                     sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2), sorted.end());
    const double median = sorted[sorted.size() / 2];
    if (median <= budget_) return std::nullopt;
    char took[96];
    std::snprintf(took, sizeof took,
                  "frames take %.1f ms, over the %.1f ms budget: ", median * 1000.0,
                  budget_ * 1000.0);
    // Anti-aliasing first: on llvmpipe it costs the most, growing with the triangles drawn
    // (docs/performance.md).
    if (quality_.msaa > 1) {
        quality_.msaa = 1;
        return std::string(took) + "anti-aliasing off (View > Anti-aliasing)";
    }
    if (quality_.shadows && quality_.shadow_map_size > kSmallestShadowMap) {
        quality_.shadow_map_size = std::max(kSmallestShadowMap, quality_.shadow_map_size / 2);
        return std::string(took) + "shadow maps of " + std::to_string(quality_.shadow_map_size) +
               " texels (View > Shadows off draws faster)";
    }
    if (quality_.reflection_size > kSmallestReflectionMap) {
        quality_.reflection_size = std::max(kSmallestReflectionMap, quality_.reflection_size / 2);
        return std::string(took) + "reflections of other models in cube maps of " +
               std::to_string(quality_.reflection_size) +
               " pixels (View > Reflections of other models off draws faster)";
    }
    return std::nullopt; // nothing cheaper left to do on its own
}

} // namespace animator
