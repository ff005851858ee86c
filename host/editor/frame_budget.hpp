// Keeping the 3D view within its frame budget (60 fps): while frames come one after another
// (playing, dragging), when the median of the last frames takes longer than the budget, the view
// is drawn more cheaply, one step at a time with one line each: no anti-aliasing, then no
// reflections of other models, then coarser levels of detail (mirrors and glass too), then shadow
// maps of half the texels, then fewer pixels (75%, then 50% of the view's along each side,
// stretched onto it). The View menu's
// settings stay as chosen; choosing them again starts over (docs/performance.md, "Shadows and
// anti-aliasing").
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace animator {

// How the 3D view is drawn.
struct ViewQuality {
    bool shadows = true;
    int shadow_map_size = 1024;
    int msaa = 4;
    int reflection_size = 128; // the models' cube maps of the models around them (0: none)
    int resolution = 100;      // percent of the view's pixels drawn along each side
    // Levels of detail: pixels a surface may stray (RenderOptions::detail_pixels), and whether
    // mirrors and glass take levels too (RenderOptions::mirror_levels).
    double detail_pixels = 0.5;
    bool mirror_levels = false;
    bool operator==(const ViewQuality &o) const {
        return shadows == o.shadows && shadow_map_size == o.shadow_map_size && msaa == o.msaa &&
               reflection_size == o.reflection_size && resolution == o.resolution &&
               detail_pixels == o.detail_pixels && mirror_levels == o.mirror_levels;
    }
};

// The levels of detail the budget takes: surfaces within 2 pixels of the mesh's (a ball 26
// pixels across then draws about a third of the triangles; docs/performance.md).
constexpr double kCoarseDetailPixels = 2.0;

// The smallest shadow map the budget lowers to. (Resolutions go down the View menu's,
// kResolutions, to its lowest.)
constexpr int kSmallestShadowMap = 512;

class FrameBudget {
  public:
    // `budget` seconds a frame, judged on the median of `window` frames, or of the frames of the
    // last `span` seconds when they are fewer (at least 3): at 3 frames a second a step is taken
    // after a second, not ten.
    explicit FrameBudget(double budget = 1.0 / 60.0, int window = 30, double span = 1.0);

    // Starts over from `chosen` (the View menu's settings, at the start or when changed).
    void choose(const ViewQuality &chosen);
    // One frame took `seconds` (count only frames drawn back to back). Returns the line to say
    // when the quality was lowered.
    std::optional<std::string> frame(double seconds);
    // Frames stopped coming back to back (idle): the next ones start a new window.
    void pause() { times_.clear(); }

    const ViewQuality &quality() const { return quality_; }

  private:
    double budget_;
    int window_;
    double span_;
    ViewQuality quality_;
    std::vector<double> times_;
};

} // namespace animator
