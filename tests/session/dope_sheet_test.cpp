// The Timeline's geometry (editor/dope_sheet_layout.hpp): times across the tracks and back, the
// rows, the ruler's ticks in seconds and frames, hitting keys with a click and a box, how far a
// drag retimes keys, zoom and pan, the spans a model is released from its keys, collision ticks.
// The Timeline docked along the bottom (editor/view_layout.hpp) is in view_layout_test.cpp.
#include "editor/dope_sheet_layout.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace animator;

namespace {

// The Timeline's content region at 1280 x 720 (right of the 340 px Animator Interface, 160 px
// tall less its title bar and padding): 914 x 125 px at (358, 587).
const ScreenRect kContent{358, 587, 914, 125};

DopeSheetLayout fitted(double max_s, int rows = 3) {
    const DopeSheetLayout probe(kContent, rows, TimeView{});
    return DopeSheetLayout(kContent, rows, fit_view(max_s, probe.track_width()));
}

ani_motion_segment segment(double t0, double t1, int motion) {
    ani_motion_segment s{};
    s.t0 = t0;
    s.t1 = t1;
    s.motion = motion;
    return s;
}

} // namespace

TEST_CASE("the fitted view spans the whole animation across the tracks", "[dope_sheet]") {
    const DopeSheetLayout l = fitted(5.0);
    // Names 110 px, 8 px at each end of the tracks for a diamond at 0 and at the max time.
    CHECK(l.track_x0() == 358 + 110 + 8);
    CHECK(l.track_x1() == 358 + 914 - 8);
    CHECK(l.x_of(0.0) == l.track_x0());
    CHECK(l.x_of(5.0) == Approx(l.track_x1()));
    CHECK(l.x_of(2.5) == Approx((l.track_x0() + l.track_x1()) / 2));
    CHECK(l.time_at(l.x_of(1.234)) == Approx(1.234));
    CHECK(l.key_x({2000, 0}) == Approx(l.x_of(2.0)));
}

TEST_CASE("rows: the camera's first, then one per model, under the ruler", "[dope_sheet]") {
    const DopeSheetLayout l = fitted(5.0, 3);
    CHECK(l.row_top(0) == 587 + 20);
    CHECK(l.row_centre(1) == 587 + 20 + 14 + 7);
    CHECK(DopeSheetLayout::row_of(KeyRef::kCamera) == 0);
    CHECK(DopeSheetLayout::row_of(1) == 2);
    CHECK(DopeSheetLayout::model_of(2) == 1);
    CHECK(l.key_y({0, KeyRef::kCamera}) == l.row_centre(0));
    CHECK(l.row_at(587 + 10) == -1);            // the ruler
    CHECK(l.row_at(587 + 20) == 0);
    CHECK(l.row_at(587 + 20 + 14 * 3 - 1) == 2);
    CHECK(l.row_at(587 + 20 + 14 * 3) == -1);   // under the last row
    CHECK(l.max_scroll() == 0.0);

    // Twelve rows do not fit in 105 px: they scroll, and scrolled rows go up.
    const DopeSheetLayout many(kContent, 12, TimeView{}, 30.0);
    CHECK(many.max_scroll() == 12 * 14 - 105);
    CHECK(many.row_top(0) == 587 + 20 - 30);
    CHECK(many.row_at(587 + 20) == 2); // row 2 spans 20 + 28 - 30 = 18 .. 32 px below the top
}

TEST_CASE("a click hits the nearest key of its row, a box holds the keys whose centres it covers", "[dope_sheet]") {
    const DopeSheetLayout l = fitted(5.0);
    const std::vector<KeyRef> keys = {{0, KeyRef::kCamera}, {0, 0}, {0, 1}, {2000, 0}, {2100, 0}, {3000, 1}};
    const double y0 = l.row_centre(1);
    CHECK(l.key_at(keys, l.x_of(2.0), y0) == KeyRef{2000, 0});
    CHECK(l.key_at(keys, l.x_of(2.0) + 4, y0 + 5) == KeyRef{2000, 0});
    CHECK(l.key_at(keys, l.x_of(2.1) - 1, y0) == KeyRef{2100, 0}); // 17 px apart: the nearer
    CHECK_FALSE(l.key_at(keys, l.x_of(2.5), y0));                     // between keys
    CHECK_FALSE(l.key_at(keys, l.x_of(3.0), y0));                     // b's key, on a's row
    CHECK(l.key_at(keys, l.x_of(3.0), l.row_centre(2)) == KeyRef{3000, 1});
    CHECK_FALSE(l.key_at(keys, l.x_of(0.0), 587 + 5));                // on the ruler
    CHECK(l.key_at(keys, l.x_of(0.0), l.row_centre(0)) == KeyRef{0, KeyRef::kCamera});

    const std::vector<KeyRef> boxed = l.keys_in_box(keys, l.x_of(1.9), l.row_top(2) + 13, l.x_of(3.5), l.row_top(1));
    const std::vector<KeyRef> expected = {{2000, 0}, {2100, 0}, {3000, 1}};
    CHECK(boxed == expected);
    CHECK(l.keys_in_box(keys, l.x_of(4.0), l.row_top(0), l.x_of(4.5), l.row_top(2)).empty());
}

TEST_CASE("the ruler ticks frames and seconds, labelled in seconds and frames", "[dope_sheet]") {
    CHECK(frame_label(0, 30) == "0s");
    CHECK(frame_label(90, 30) == "3s");
    CHECK(frame_label(75, 30) == "2:15");
    CHECK(frame_label(3, 30) == "0:03");

    // 5 s over 788 px: 158 px a second. Labels at least 64 px apart: every 15 frames (79 px),
    // minor ticks every 5 frames (26 px; a tick a frame would be 5 px apart, too close).
    const DopeSheetLayout l = fitted(5.0);
    const std::vector<RulerTick> ticks = ruler_ticks(l, 5.0, 30);
    REQUIRE(!ticks.empty());
    CHECK(ticks.front().frame == 0);
    CHECK(ticks.front().major);
    CHECK(ticks.front().label == "0s");
    CHECK(ticks.front().x == l.x_of(0.0));
    CHECK(ticks.back().frame == 150);
    int majors = 0;
    for (const RulerTick &t : ticks) {
        CHECK(t.frame % 5 == 0);
        CHECK(t.major == (t.frame % 15 == 0));
        CHECK(t.x == Approx(l.x_of(static_cast<double>(t.frame) / 30.0)));
        majors += t.major;
        if (t.frame == 45) CHECK(t.label == "1:15");
        if (t.frame == 60) CHECK(t.label == "2s");
    }
    CHECK(majors == 11);
    CHECK(ticks.size() == 31);

    // A long animation: labels every so many seconds, no tick per frame.
    const DopeSheetLayout hour = fitted(3600.0);
    const std::vector<RulerTick> long_ticks = ruler_ticks(hour, 3600.0, 30);
    CHECK(long_ticks.size() < 200);
    for (const RulerTick &t : long_ticks)
        if (t.major) CHECK(t.frame % (300 * 30) == 0);
}

TEST_CASE("a click on the ruler puts the playhead on the nearest frame", "[dope_sheet]") {
    CHECK(snap_to_frame(2.5, 30, 5000) == 2500);
    CHECK(snap_to_frame(2.51, 30, 5000) == 2500);
    CHECK(snap_to_frame(2.52, 30, 5000) == 2533);  // frame 76: round(76000 / 30)
    CHECK(snap_to_frame(0.01, 30, 5000) == 0);
    CHECK(snap_to_frame(-1.0, 30, 5000) == 0);
    CHECK(snap_to_frame(9.0, 30, 5000) == 5000);
}

TEST_CASE("dragging keys retimes them by whole frames, after 0 and up to the max time", "[dope_sheet]") {
    const DopeSheetLayout l = fitted(5.0);
    const double pps = l.view().pixels_per_second;
    const std::vector<KeyRef> moving = {{2000, 0}, {3000, 1}};
    // The grabbed key lands on the frame nearest the pointer: 2000 + 1000 ms.
    CHECK(retime_offset(l, {2000, 0}, moving, 600, 600 + pps, 30, 5000) == 1000);
    CHECK(retime_offset(l, {2000, 0}, moving, 600, 600 + 0.51 * pps, 30, 5000) == 500); // 2510: frame 75
    CHECK(retime_offset(l, {2000, 0}, moving, 600, 600 + 0.02 * pps, 30, 5000) == 33);   // frame 61
    CHECK(retime_offset(l, {2000, 0}, moving, 600, 600, 30, 5000) == 0);
    // Stopped at the max time by the last key (3000 + 2000), and short of 0 by the first.
    CHECK(retime_offset(l, {2000, 0}, moving, 600, 600 + 4 * pps, 30, 5000) == 2000);
    CHECK(retime_offset(l, {3000, 1}, moving, 600, 600 - 4 * pps, 30, 5000) == -1999);
    CHECK(retime_offset(l, {2000, 0}, {}, 600, 900, 30, 5000) == 0);
}

TEST_CASE("the wheel zooms about the pointer, down to a frame every 120 px, panning stays inside", "[dope_sheet]") {
    const DopeSheetLayout l = fitted(10.0);
    const double x = l.x_of(4.0);
    const TimeView in = zoom_view(l, x, 2.0, 10.0, 30);
    CHECK(in.pixels_per_second == Approx(l.view().pixels_per_second * 1.25 * 1.25));
    const DopeSheetLayout zoomed(kContent, 3, in);
    CHECK(zoomed.time_at(x) == Approx(4.0)); // the time under the pointer stays under it
    // Out again: never past the whole animation.
    const TimeView out = zoom_view(zoomed, x, -10.0, 10.0, 30);
    CHECK(out.pixels_per_second == l.view().pixels_per_second);
    CHECK(out.start_s == Approx(0.0).margin(1e-9));
    // Far in: a frame is at most 120 px wide.
    CHECK(zoom_view(l, x, 100.0, 10.0, 30).pixels_per_second == Approx(120.0 * 30));
    // Panning: later by 100 px, and not before 0 nor past the end.
    const TimeView later = pan_view(zoomed, 100.0, 10.0, 30);
    CHECK(later.start_s == Approx(in.start_s + 100.0 / in.pixels_per_second));
    CHECK(pan_view(zoomed, -1e6, 10.0, 30).start_s == 0.0);
    const TimeView last = pan_view(zoomed, 1e6, 10.0, 30);
    CHECK(DopeSheetLayout(kContent, 3, last).time_at(zoomed.track_x1()) == Approx(10.0));
    // A shorter animation (max time changed) clamps the view in.
    CHECK(clamp_view(last, 2.0, l.track_width(), 30) == fit_view(2.0, l.track_width()));
}

TEST_CASE("released spans: free flight and rest, joined where contiguous, keyed spans are not", "[dope_sheet]") {
    const std::vector<ani_motion_segment> segments = {
        segment(0.0, 1.0, ANI_MOTION_KEYED), segment(1.0, 1.5, ANI_MOTION_FREE), segment(1.5, 2.0, ANI_MOTION_FREE),
        segment(2.0, 3.0, ANI_MOTION_REST), segment(3.0, 4.0, ANI_MOTION_KEYED), segment(4.0, 5.0, ANI_MOTION_FREE)};
    SegmentStore store(1);
    for (const ani_motion_segment &s : segments) store.log(s);
    store.file();
    const std::vector<ReleasedSpan> spans = released_spans(store[0]);
    REQUIRE(spans.size() == 3);
    CHECK(spans[0].t0 == 1.0);
    CHECK(spans[0].t1 == 2.0);
    CHECK(spans[0].motion == ANI_MOTION_FREE);
    CHECK(spans[1].t0 == 2.0);
    CHECK(spans[1].t1 == 3.0);
    CHECK(spans[1].motion == ANI_MOTION_REST);
    CHECK(spans[2].t0 == 4.0);
    CHECK(released_spans({}).empty());
}

TEST_CASE("a collision ticks the rows of both its models where its time is", "[dope_sheet]") {
    const DopeSheetLayout l = fitted(5.0, 4);
    ani::HugeVector<ani_collision_event> events(3);
    events[0].t = 0.903;
    events[0].a = 1;
    events[0].b = 0;
    events[1].t = 2.0;
    events[1].a = 2;
    events[1].b = ANI_NO_MODEL; // a world boundary has no row
    events[2].t = 7.0;          // past what is shown
    events[2].a = 0;
    events[2].b = 1;
    const std::vector<EventTick> ticks = event_ticks(l, events, 3);
    REQUIRE(ticks.size() == 3);
    CHECK(ticks[0].x == Approx(l.x_of(0.903)));
    CHECK(ticks[0].row == 2);
    CHECK(ticks[1].row == 1);
    CHECK(ticks[2].row == 3);
    CHECK(ticks[2].x == Approx(l.x_of(2.0)));
}
