#include "editor/frame_budget.hpp"

#include "editor/view_settings.hpp"

#include <algorithm>
#include <cstdio>
#include <numeric>

namespace animator {

FrameBudget::FrameBudget(double budget, int window, double span)
    : budget_(budget), window_(std::max(window, 1)), span_(span) {}

void FrameBudget::choose(const ViewQuality &chosen) {
    quality_ = chosen;
    times_.clear();
}

std::optional<std::string> FrameBudget::frame(double seconds) {
    times_.push_back(seconds);
    const int count = static_cast<int>(times_.size());
    const double spent = std::accumulate(times_.begin(), times_.end(), 0.0);
    if (count < window_ && !(count >= std::min(3, window_) && spent >= span_)) return std::nullopt;
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
    // Then the reflections' cube maps: six more views of the scene for each reflective or
    // transparent model (with 100 models they cost more than anti-aliasing).
    if (quality_.reflection_size > 0) {
        quality_.reflection_size = 0;
        return std::string(took) +
               "reflections of other models off (View > Reflections of other models)";
    }
    // Then coarser levels of detail, mirrors and glass included: on llvmpipe a small triangle
    // costs about as much as a hundred pixels, and a moving ball's outline a pixel or two
    // coarser is hard to see (docs/performance.md).
    if (quality_.detail_pixels > 0.0 &&
        (quality_.detail_pixels < kCoarseDetailPixels || !quality_.mirror_levels)) {
        quality_.detail_pixels = std::max(quality_.detail_pixels, kCoarseDetailPixels);
        quality_.mirror_levels = true;
        return std::string(took) + "coarser levels of detail (mirrors and glass too)";
    }
    // Shadows last (they are what stops a ball from floating), and only made coarser.
    if (quality_.shadows && quality_.shadow_map_size > kSmallestShadowMap) {
        quality_.shadow_map_size = std::max(kSmallestShadowMap, quality_.shadow_map_size / 2);
        return std::string(took) + "shadow maps of " + std::to_string(quality_.shadow_map_size) +
               " texels (View > Shadows off draws faster)";
    }
    // Then fewer pixels, down the View menu's resolutions: on llvmpipe every pixel of the sky,
    // the floor and the models is shaded on the processor, so a view drawn at 75% along each side
    // costs about half, at 50% a quarter, of its fill (docs/performance.md).
    for (const int lower : kResolutions)
        if (lower < quality_.resolution) {
            quality_.resolution = lower;
            return std::string(took) + "the view drawn at " + std::to_string(lower) +
                   "% resolution (View > Resolution)";
        }
    return std::nullopt; // nothing cheaper left to do on its own
}

} // namespace animator
