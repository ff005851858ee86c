// The Timeline's (dope sheet's, editor/dope_sheet.hpp) geometry, without a window: where a time
// is across the tracks and back, the rows (the camera's first, then one per model), the ruler's
// ticks in seconds and frames, which key a click hits or a box holds, how far a drag retimes
// keys, the spans a model is released from its keys and where collisions tick. Pure, so the
// maths the screen is drawn with is tested on its own (tests/session/dope_sheet_test.cpp), and
// the end-to-end tests find the pixels where it says (tests/editor/cases_dope_sheet.py).
#pragma once

#include "document/key_edits.hpp"
#include "editor/view_layout.hpp"
#include "timeline/segment_store.hpp"

#include <animator/huge_pages.hpp>
#include <animator/physics.h>

#include <algorithm>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace animator {

// The span of time shown: the time at the tracks' left end and the scale.
struct TimeView {
    double start_s = 0.0;
    double pixels_per_second = 100.0;
    bool operator==(const TimeView &o) const { return start_s == o.start_s && pixels_per_second == o.pixels_per_second; }
};

// Sizes in window pixels (Dear ImGui's default font is 13 px).
struct DopeSheetMetrics {
    double label_width = 110.0; // the names of the rows
    double ruler_height = 20.0;
    double row_height = 14.0;
    double track_pad = 8.0;     // room at each end of the tracks for a diamond at 0 and at the max time
};

class DopeSheetLayout {
  public:
    // `rect`: the Timeline's content region; `rows`: the camera's and one per model.
    DopeSheetLayout(ScreenRect rect, int rows, TimeView view, double scroll = 0.0, DopeSheetMetrics m = {})
        : rect_(rect), rows_(rows), view_(view), scroll_(scroll), m_(m) {}

    const ScreenRect &rect() const { return rect_; }
    const DopeSheetMetrics &metrics() const { return m_; }
    const TimeView &view() const { return view_; }
    int rows() const { return rows_; }
    double scroll() const { return scroll_; }

    // The tracks' ends: where start_s is, and the last pixel a time is drawn at.
    double track_x0() const { return rect_.x + m_.label_width + m_.track_pad; }
    double track_x1() const { return rect_.x + rect_.width - m_.track_pad; }
    double track_width() const { return track_x1() - track_x0(); }
    double x_of(double t) const { return track_x0() + (t - view_.start_s) * view_.pixels_per_second; }
    double time_at(double x) const { return view_.start_s + (x - track_x0()) / view_.pixels_per_second; }

    // The ruler along the top, the rows under it (scrolled up by scroll()).
    ScreenRect ruler() const { return {rect_.x + m_.label_width, rect_.y, rect_.width - m_.label_width, m_.ruler_height}; }
    ScreenRect rows_area() const {
        return {rect_.x, rect_.y + m_.ruler_height, rect_.width, std::max(0.0, rect_.height - m_.ruler_height)};
    }
    ScreenRect tracks() const {
        const ScreenRect r = rows_area();
        return {rect_.x + m_.label_width, r.y, rect_.width - m_.label_width, r.height};
    }
    double row_top(int row) const { return rect_.y + m_.ruler_height + row * m_.row_height - scroll_; }
    double row_centre(int row) const { return row_top(row) + m_.row_height / 2.0; }
    // The row at y (on the rows area, not scrolled out of it), or -1.
    int row_at(double y) const;
    // The most the rows scroll: all of them shown, the last at the bottom.
    double max_scroll() const;
    static int row_of(int model) { return model + 1; } // KeyRef::kCamera (-1) is row 0
    static int model_of(int row) { return row - 1; }

    // A key's diamond: its centre and half its width.
    double diamond_radius() const { return m_.row_height * 0.4; }
    double key_x(const KeyRef &k) const { return x_of(static_cast<double>(k.time_ms) / 1000.0); }
    double key_y(const KeyRef &k) const { return row_centre(row_of(k.model)); }

    // The key whose diamond is at (x, y), the nearest when several overlap, of `keys`.
    std::optional<KeyRef> key_at(const std::vector<KeyRef> &keys, double x, double y) const;
    // The keys whose diamonds' centres are in the box between two corners (any order).
    std::vector<KeyRef> keys_in_box(const std::vector<KeyRef> &keys, double x0, double y0, double x1, double y1) const;

  private:
    ScreenRect rect_;
    int rows_;
    TimeView view_;
    double scroll_;
    DopeSheetMetrics m_;
};

// The whole animation across `track_width` pixels.
TimeView fit_view(double max_s, double track_width);
// Keeps the scale within [the whole animation, a frame every kMaxPixelsPerFrame px] and the
// span shown inside [0, max_s].
TimeView clamp_view(TimeView view, double max_s, double track_width, double fps);
// The wheel over the tracks: `notches` up zoom in by 1.25 each, about the time under x.
TimeView zoom_view(const DopeSheetLayout &layout, double x, double notches, double max_s, double fps);
// Shifts the span by `dx` pixels of the tracks (positive: to later times).
TimeView pan_view(const DopeSheetLayout &layout, double dx, double max_s, double fps);
constexpr double kMaxPixelsPerFrame = 120.0;
constexpr double kWheelZoom = 1.25;

// The ruler: a tick at each frame, second or run of seconds, a label on each major one.
struct RulerTick {
    std::int64_t frame = 0;
    double x = 0.0;
    bool major = false;
    std::string label; // majors only: "3s" at whole seconds, else "3:15" (3 s and 15 frames)
};
// Major ticks at least `label_spacing` px apart, minor ones between them at least 8 px apart,
// within [0, max_s] and the tracks.
std::vector<RulerTick> ruler_ticks(const DopeSheetLayout &layout, double max_s, double fps, double label_spacing = 64.0);
// "3s" or "3:15": frame `frame` at `fps` (a whole number of frames a second).
std::string frame_label(std::int64_t frame, double fps);
// The frame nearest to t seconds, in whole ms (time_steps.hpp: frame k is at round(k * 1000 / fps)),
// clamped to [0, max_ms]: where a click on the ruler puts the playhead.
std::int64_t snap_to_frame(double t, double fps, std::int64_t max_ms);

// How far dragging `grabbed` (one of `moving`) from x0 to x retimes `moving`: the grabbed key
// lands on the frame nearest the pointer, and every key stays in (0, max_ms] (t = 0 belongs to
// the initial placement, which `moving` must not hold).
std::int64_t retime_offset(const DopeSheetLayout &layout, const KeyRef &grabbed, const std::vector<KeyRef> &moving,
                           double x0, double x, double fps, std::int64_t max_ms);

// Where a model is released from its keys: the backend's segments, FREE (flying) or REST (at
// rest), contiguous ones of a kind joined. In time order.
struct ReleasedSpan {
    double t0 = 0.0, t1 = 0.0;
    int motion = ANI_MOTION_FREE;
};
std::vector<ReleasedSpan> released_spans(SegmentSpan segments);

// A collision on the rows of its two models (a world boundary has no row), in the tracks.
struct EventTick {
    double x = 0.0;
    int row = 0;
};
std::vector<EventTick> event_ticks(const DopeSheetLayout &layout, const ani::HugeVector<ani_collision_event> &events,
                                   int models);

} // namespace animator
