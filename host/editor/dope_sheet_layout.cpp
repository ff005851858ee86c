#include "editor/dope_sheet_layout.hpp"

#include <cmath>
#include <cstdio>
#include <limits>

namespace animator {

namespace {

// Steps between ruler ticks, in frames: parts of a second, then runs of seconds.
std::vector<std::int64_t> tick_steps(double fps) {
    const auto per_second = std::max<std::int64_t>(1, std::llround(fps));
    std::vector<std::int64_t> steps;
    for (std::int64_t f : {1, 2, 5, 10, 15})
        if (f < per_second && per_second % f == 0) steps.push_back(f);
    for (std::int64_t s : {1, 2, 5, 10, 15, 30, 60, 120, 300, 600, 900, 1800, 3600, 7200, 18000, 36000, 72000, 180000, 360000})
        steps.push_back(s * per_second);
    return steps;
}

} // namespace

int DopeSheetLayout::row_at(double y) const {
    const ScreenRect area = rows_area();
    if (y < area.y || y >= area.y + area.height) return -1;
    const auto row = static_cast<int>(std::floor((y - row_top(0)) / m_.row_height));
    return row >= 0 && row < rows_ ? row : -1;
}

double DopeSheetLayout::max_scroll() const { return std::max(0.0, rows_ * m_.row_height - rows_area().height); }

std::optional<KeyRef> DopeSheetLayout::key_at(const std::vector<KeyRef> &keys, double x, double y) const {
    const int row = row_at(y);
    if (row < 0 || x < rect_.x + m_.label_width) return std::nullopt;
    std::optional<KeyRef> best;
    double best_dx = diamond_radius() + 2.0; // a little forgiving: a diamond is small
    for (const KeyRef &k : keys) {
        if (row_of(k.model) != row) continue;
        const double dx = std::abs(key_x(k) - x);
        if (dx <= best_dx) {
            best_dx = dx;
            best = k;
        }
    }
    return best;
}

std::vector<KeyRef> DopeSheetLayout::keys_in_box(const std::vector<KeyRef> &keys, double x0, double y0, double x1,
                                                 double y1) const {
    if (x0 > x1) std::swap(x0, x1);
    if (y0 > y1) std::swap(y0, y1);
    std::vector<KeyRef> out;
    for (const KeyRef &k : keys) {
        const double x = key_x(k), y = key_y(k);
        if (x >= x0 && x <= x1 && y >= y0 && y <= y1) out.push_back(k);
    }
    return out;
}

TimeView fit_view(double max_s, double track_width) {
    TimeView v;
    v.start_s = 0.0;
    v.pixels_per_second = max_s > 0.0 && track_width > 0.0 ? track_width / max_s : 100.0;
    return v;
}

TimeView clamp_view(TimeView v, double max_s, double track_width, double fps) {
    if (!(max_s > 0.0) || !(track_width > 0.0)) return fit_view(max_s, track_width);
    const double least = track_width / max_s, most = std::max(least, kMaxPixelsPerFrame * fps);
    if (!std::isfinite(v.pixels_per_second)) v.pixels_per_second = least;
    v.pixels_per_second = std::clamp(v.pixels_per_second, least, most);
    const double span = track_width / v.pixels_per_second;
    if (!std::isfinite(v.start_s)) v.start_s = 0.0;
    v.start_s = std::clamp(v.start_s, 0.0, std::max(0.0, max_s - span));
    return v;
}

TimeView zoom_view(const DopeSheetLayout &layout, double x, double notches, double max_s, double fps) {
    const double t = layout.time_at(x);
    TimeView v = layout.view();
    v.pixels_per_second *= std::pow(kWheelZoom, notches);
    v = clamp_view(v, max_s, layout.track_width(), fps); // the scale first, then where
    v.start_s = t - (x - layout.track_x0()) / v.pixels_per_second;
    return clamp_view(v, max_s, layout.track_width(), fps);
}

TimeView pan_view(const DopeSheetLayout &layout, double dx, double max_s, double fps) {
    TimeView v = layout.view();
    v.start_s += dx / v.pixels_per_second;
    return clamp_view(v, max_s, layout.track_width(), fps);
}

std::string frame_label(std::int64_t frame, double fps) {
    const auto per_second = std::max<std::int64_t>(1, std::llround(fps));
    char text[48];
    const long long s = frame / per_second, f = frame % per_second;
    if (f == 0) std::snprintf(text, sizeof text, "%llds", s);
    else std::snprintf(text, sizeof text, "%lld:%02lld", s, f);
    return text;
}

std::int64_t snap_to_frame(double t, double fps, std::int64_t max_ms) {
    if (!(fps > 0.0) || !std::isfinite(t)) return 0;
    const double k = std::round(t * fps);
    const auto ms = static_cast<std::int64_t>(std::llround(k * 1000.0 / fps));
    return std::clamp<std::int64_t>(ms, 0, max_ms);
}

std::vector<RulerTick> ruler_ticks(const DopeSheetLayout &layout, double max_s, double fps, double label_spacing) {
    std::vector<RulerTick> ticks;
    const double pps = layout.view().pixels_per_second;
    if (!(fps > 0.0) || !(pps > 0.0) || !(max_s > 0.0)) return ticks;
    const std::vector<std::int64_t> steps = tick_steps(fps);
    auto px = [&](std::int64_t frames) { return static_cast<double>(frames) / fps * pps; };
    std::int64_t major = steps.back();
    for (std::int64_t s : steps)
        if (px(s) >= label_spacing) {
            major = s;
            break;
        }
    std::int64_t minor = major;
    for (std::int64_t s : steps)
        if (s < major && major % s == 0 && px(s) >= 8.0) {
            minor = s;
            break;
        }
    const double pad = layout.metrics().track_pad;
    const double t0 = std::max(0.0, layout.time_at(layout.track_x0() - pad));
    const double t1 = std::min(max_s, layout.time_at(layout.track_x1() + pad));
    auto k = static_cast<std::int64_t>(std::ceil(t0 * fps / static_cast<double>(minor) - 1e-9)) * minor;
    for (int n = 0; n < 4000; ++n, k += minor) {
        const double t = static_cast<double>(k) / fps;
        if (t > t1 + 1e-9) break;
        RulerTick tick;
        tick.frame = k;
        tick.x = layout.x_of(t);
        tick.major = k % major == 0;
        if (tick.major) tick.label = frame_label(k, fps);
        ticks.push_back(tick);
    }
    return ticks;
}

std::int64_t retime_offset(const DopeSheetLayout &layout, const KeyRef &grabbed, const std::vector<KeyRef> &moving,
                           double x0, double x, double fps, std::int64_t max_ms) {
    if (moving.empty()) return 0;
    const double t = static_cast<double>(grabbed.time_ms) / 1000.0 + (x - x0) / layout.view().pixels_per_second;
    const std::int64_t lands = snap_to_frame(t, fps, std::numeric_limits<std::int64_t>::max() / 2);
    std::int64_t first = moving.front().time_ms, last = first;
    for (const KeyRef &k : moving) {
        first = std::min(first, k.time_ms);
        last = std::max(last, k.time_ms);
    }
    const std::int64_t lo = 1 - first, hi = max_ms - last;
    if (lo > hi) return 0;
    return std::clamp<std::int64_t>(lands - grabbed.time_ms, lo, hi);
}

std::vector<ReleasedSpan> released_spans(SegmentSpan segments) {
    std::vector<ReleasedSpan> spans;
    for (const ani_motion_segment &s : segments) {
        if (s.motion != ANI_MOTION_FREE && s.motion != ANI_MOTION_REST && s.motion != ANI_MOTION_CARRIED) continue;
        if (!spans.empty() && spans.back().motion == s.motion && s.t0 <= spans.back().t1 + 1e-9 && s.t0 >= spans.back().t0) {
            spans.back().t1 = std::max(spans.back().t1, s.t1);
            continue;
        }
        spans.push_back({s.t0, s.t1, s.motion});
    }
    return spans;
}

std::vector<EventTick> event_ticks(const DopeSheetLayout &layout, const ani::HugeVector<ani_collision_event> &events,
                                   int models) {
    std::vector<EventTick> ticks;
    const double t0 = layout.time_at(layout.track_x0() - layout.metrics().track_pad);
    const double t1 = layout.time_at(layout.track_x1() + layout.metrics().track_pad);
    for (const ani_collision_event &e : events) {
        if (e.t < t0 || e.t > t1) continue;
        const double x = layout.x_of(e.t);
        for (std::uint32_t m : {e.a, e.b})
            if (m != ANI_NO_MODEL && m < static_cast<std::uint32_t>(models))
                ticks.push_back({x, DopeSheetLayout::row_of(static_cast<int>(m))});
    }
    return ticks;
}

} // namespace animator
